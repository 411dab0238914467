#include "os_outputs/unix_listener.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>
#include <utility>

#include "core/error.hpp"

namespace onetip::os_outputs {

namespace {

std::string quoted(const std::string& path) { return "spnav socket '" + path + "'"; }

std::string errnoText(int err) { return std::strerror(err); }

bool fillAddress(const std::string& path, sockaddr_un& addr) {
  addr = {};
  addr.sun_family = AF_UNIX;
  if (path.empty() || path.size() >= sizeof(addr.sun_path)) return false;
  std::memcpy(addr.sun_path, path.c_str(), path.size() + 1);
  return true;
}

std::string directoryOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

// True when a server accepts connections at the socket `path`.
bool socketIsLive(const std::string& path) {
  sockaddr_un addr{};
  if (!fillAddress(path, addr)) return false;
  const int probe = ::socket(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (probe < 0) return false;
  const int rc = ::connect(probe, reinterpret_cast<const sockaddr*>(&addr), sizeof(addr));
  const int err = errno;
  ::close(probe);
  if (rc == 0) return true;
  return err == EAGAIN || err == EINPROGRESS;  // backlog full: alive, just busy
}

void checkExisting(const std::string& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) {
    if (errno == ENOENT) return;
    throw InputError(quoted(path) + ": cannot inspect it: " + errnoText(errno));
  }
  if (!S_ISSOCK(st.st_mode)) throw InputError(quoted(path) + ": exists and is not a socket; refusing to replace it");
  if (socketIsLive(path)) throw InputError(quoted(path) + ": another server is listening there");
}

// Takes the lock file "<path>.lock" beside the socket (flock, held while the
// listener lives): of two servers started together on one path, one gets it and
// the other is refused before either looks at the socket. The file is unlinked
// by its holder on close; a holder whose file was unlinked and replaced between
// open and flock retries on the new one, so two never hold "the" lock at once.
int lockBeside(const std::string& path, struct stat& locked) {
  const std::string lock = path + ".lock";
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(lock.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0600);
    if (fd < 0) throw InputError(quoted(path) + ": cannot open its lock file '" + lock + "': " + errnoText(errno));
    struct stat now {};
    if (::fstat(fd, &locked) != 0 || !S_ISREG(locked.st_mode)) {
      ::close(fd);
      throw InputError(quoted(path) + ": its lock file '" + lock + "' is not a regular file; refusing to use it");
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      ::close(fd);
      if (err == EWOULDBLOCK) throw InputError(quoted(path) + ": another server is listening there or starting (it holds '" + lock + "')");
      throw InputError(quoted(path) + ": cannot lock '" + lock + "': " + errnoText(err));
    }
    if (::lstat(lock.c_str(), &now) == 0 && now.st_dev == locked.st_dev && now.st_ino == locked.st_ino) return fd;
    ::close(fd);  // unlinked by its previous holder meanwhile: lock the file now at that name
  }
  throw InputError(quoted(path) + ": its lock file '" + lock + "' keeps being replaced");
}

// Removes the temporary directory and everything we put in it.
struct TempDir {
  std::string dir, socket;
  ~TempDir() {
    if (!socket.empty()) ::unlink(socket.c_str());
    if (!dir.empty()) ::rmdir(dir.c_str());
  }
};

}  // namespace

UnixListener::~UnixListener() { close(); }

UnixListener::UnixListener(UnixListener&& other) noexcept { *this = std::move(other); }

UnixListener& UnixListener::operator=(UnixListener&& other) noexcept {
  if (this != &other) {
    close();
    fd_ = std::exchange(other.fd_, -1);
    path_ = std::move(other.path_);
    device_ = other.device_;
    inode_ = other.inode_;
    lock_fd_ = std::exchange(other.lock_fd_, -1);
    lock_device_ = other.lock_device_;
    lock_inode_ = other.lock_inode_;
  }
  return *this;
}

UnixListener UnixListener::listenAt(const std::string& path, int backlog) {
  sockaddr_un addr{};
  if (!fillAddress(path, addr)) {
    throw InputError(quoted(path) + ": path must be 1 to " + std::to_string(sizeof(addr.sun_path) - 1) +
                     " bytes long");
  }
  const std::string dir = directoryOf(path);
  struct stat dst {};
  if (::stat(dir.c_str(), &dst) != 0 || !S_ISDIR(dst.st_mode)) {
    throw InputError(quoted(path) + ": directory '" + dir + "' does not exist");
  }
  UnixListener out;
  struct stat locked {};
  out.lock_fd_ = lockBeside(path, locked);
  out.path_ = path;
  out.lock_device_ = locked.st_dev;
  out.lock_inode_ = locked.st_ino;
  checkExisting(path);

  TempDir temp;
  std::string templ = dir + "/.onetip-spnav-XXXXXX";
  if (::mkdtemp(templ.data()) == nullptr) {
    throw InputError(quoted(path) + ": cannot create a temporary directory in '" + dir + "': " + errnoText(errno));
  }
  temp.dir = templ;
  const std::string staging = temp.dir + "/s";
  sockaddr_un staging_addr{};
  if (!fillAddress(staging, staging_addr)) {
    throw InputError(quoted(path) + ": directory '" + dir + "' is too long for the temporary socket beside it");
  }

  out.fd_ = ::socket(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (out.fd_ < 0) throw InputError(quoted(path) + ": socket(): " + errnoText(errno));
  if (::bind(out.fd_, reinterpret_cast<const sockaddr*>(&staging_addr), sizeof(staging_addr)) != 0) {
    throw InputError(quoted(path) + ": bind: " + errnoText(errno));
  }
  temp.socket = staging;
  if (::chmod(staging.c_str(), S_IRUSR | S_IWUSR) != 0) {
    throw InputError(quoted(path) + ": chmod 0600: " + errnoText(errno));
  }
  if (::listen(out.fd_, backlog) != 0) throw InputError(quoted(path) + ": listen: " + errnoText(errno));
  // A stale socket at `path` is replaced atomically; a live one was refused above.
  if (::rename(staging.c_str(), path.c_str()) != 0) {
    throw InputError(quoted(path) + ": cannot move the socket into place: " + errnoText(errno));
  }
  temp.socket.clear();
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) throw InputError(quoted(path) + ": vanished after creation");
  out.path_ = path;
  out.device_ = st.st_dev;
  out.inode_ = st.st_ino;
  return out;
}

void UnixListener::close() noexcept {
  struct stat st {};
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
    if (::lstat(path_.c_str(), &st) == 0 && S_ISSOCK(st.st_mode) && st.st_dev == device_ && st.st_ino == inode_)
      ::unlink(path_.c_str());
  }
  if (lock_fd_ >= 0) {  // unlinked while still held: the next server locks a fresh file
    const std::string lock = path_ + ".lock";
    if (::lstat(lock.c_str(), &st) == 0 && st.st_dev == lock_device_ && st.st_ino == lock_inode_) ::unlink(lock.c_str());
    ::close(lock_fd_);
    lock_fd_ = -1;
  }
}

}  // namespace onetip::os_outputs
