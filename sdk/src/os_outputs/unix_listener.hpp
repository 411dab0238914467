// os_outputs/unix_listener.hpp — a listening AF_UNIX stream socket at a file
// path, readable and writable by its owner only.
//
// Creation is safe against races and against deleting what is not ours:
//   - the path must fit sockaddr_un (at most 107 bytes) and its directory exist;
//   - "<path>.lock" beside it is flock-ed for the listener's life (and removed
//     on close): a second server on the same path is refused even when both
//     start together, before either has a socket to probe;
//   - if something already exists at the path: a non-socket (file, directory,
//     symlink, ...) is never touched (InputError); a socket that still accepts
//     connections belongs to a live server (InputError); a socket that refuses
//     connections is stale and is replaced;
//   - the socket is bound inside a fresh 0700 directory beside the path,
//     chmod-ed to 0600 there and only then renamed onto the path, so it is
//     never reachable with wider permissions whatever the umask;
//   - on close the path is unlinked only if it is still this socket (same
//     device and inode), never a file someone put there since.
// The listening descriptor is non-blocking and close-on-exec.
#pragma once

#include <string>
#include <sys/types.h>

namespace onetip::os_outputs {

class UnixListener {
 public:
  UnixListener() = default;
  ~UnixListener();
  UnixListener(UnixListener&& other) noexcept;
  UnixListener& operator=(UnixListener&& other) noexcept;
  UnixListener(const UnixListener&) = delete;
  UnixListener& operator=(const UnixListener&) = delete;

  // Throws InputError naming the path when it cannot listen there.
  static UnixListener listenAt(const std::string& path, int backlog);

  int fd() const noexcept { return fd_; }
  const std::string& path() const noexcept { return path_; }
  // Closes the socket and removes the path if it is still ours.
  void close() noexcept;

 private:
  int fd_ = -1;
  std::string path_;
  dev_t device_ = 0;
  ino_t inode_ = 0;
  int lock_fd_ = -1;
  dev_t lock_device_ = 0;
  ino_t lock_inode_ = 0;
};

}  // namespace onetip::os_outputs
