#include "os_outputs/unix_listener.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
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

  UnixListener out;
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
  if (fd_ < 0) return;
  ::close(fd_);
  fd_ = -1;
  struct stat st {};
  if (::lstat(path_.c_str(), &st) == 0 && S_ISSOCK(st.st_mode) && st.st_dev == device_ && st.st_ino == inode_) {
    ::unlink(path_.c_str());
  }
}

}  // namespace onetip::os_outputs
