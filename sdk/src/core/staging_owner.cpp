#include "core/staging_owner.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cctype>
#include <climits>
#include <fstream>
#include <vector>

namespace onetip {

namespace fs = std::filesystem;

namespace {

bool allOf(const std::string& s, bool (*pred)(int)) {
  for (const unsigned char c : s)
    if (!pred(c)) return false;
  return !s.empty();
}

std::string hostName() {
  char buf[HOST_NAME_MAX + 1] = {};
  if (::gethostname(buf, sizeof buf - 1) != 0 || buf[0] == '\0') return "unknown";
  std::string host(buf);
  for (char& c : host)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-') c = '-';
  return host.substr(0, 32);  // the boot id tells hosts apart anyway
}

std::string bootId() {
  std::ifstream in("/proc/sys/kernel/random/boot_id");
  std::string line, hex;
  std::getline(in, line);
  for (const unsigned char c : line)
    if (std::isxdigit(c)) hex.push_back(static_cast<char>(std::tolower(c)));
  return hex.size() >= 16 ? hex.substr(0, 16) : "unknown";
}

std::string pidNamespace() {
  char buf[64] = {};
  const ssize_t n = ::readlink("/proc/self/ns/pid", buf, sizeof buf - 1);  // "pid:[4026531836]"
  std::string digits;
  for (ssize_t i = 0; i < n; ++i)
    if (std::isdigit(static_cast<unsigned char>(buf[i]))) digits.push_back(buf[i]);
  return digits.empty() ? "unknown" : digits;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts(1);
  for (const char c : s) {
    if (c == sep)
      parts.emplace_back();
    else
      parts.back().push_back(c);
  }
  return parts;
}

bool hostChar(int c) { return std::isalnum(c) || c == '-'; }
bool hexChar(int c) { return std::isxdigit(c) != 0; }
bool digitChar(int c) { return std::isdigit(c) != 0; }
bool alnumChar(int c) { return std::isalnum(c) != 0; }

// Opens what holds the owner's lock: the staging file itself, or the lock file inside a staging folder.
int openLockOf(const fs::path& entry) {
  struct stat st {};
  if (::lstat(entry.c_str(), &st) != 0) return -1;
  const fs::path lock = S_ISDIR(st.st_mode) ? entry / kStagingLockName : entry;
  return ::open(lock.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
}

}  // namespace

StagingOwner thisStagingOwner() {
  // The pid changes in a forked child: the rest is the same for every process of this program.
  static const StagingOwner fixed{hostName(), bootId(), pidNamespace(), 0};
  StagingOwner self = fixed;
  self.pid = static_cast<long>(::getpid());
  return self;
}

std::string stagingOwnerTag() {
  const StagingOwner o = thisStagingOwner();
  return o.host + "." + o.boot + "." + o.pidns + "." + std::to_string(o.pid);
}

std::optional<StagingOwner> parseStagingOwner(const std::string& after_infix) {
  const std::vector<std::string> f = split(after_infix, '.');
  if (f.size() != 5) return std::nullopt;
  const bool ok = allOf(f[0], hostChar) && (f[1] == "unknown" || (f[1].size() == 16 && allOf(f[1], hexChar))) &&
                  (f[2] == "unknown" || (f[2].size() <= 20 && allOf(f[2], digitChar))) && f[3].size() <= 9 &&
                  allOf(f[3], digitChar) && f[4].size() == 6 && allOf(f[4], alnumChar);
  if (!ok) return std::nullopt;
  return StagingOwner{f[0], f[1], f[2], std::stol(f[3])};
}

bool stagingAbandoned(const fs::path& entry, const StagingOwner& owner) {
  const StagingOwner self = thisStagingOwner();
  if (self.boot == "unknown" || owner.host != self.host || owner.boot != self.boot) return false;
  const int fd = openLockOf(entry);
  if (fd >= 0) {
    const bool free = lockExclusively(fd);
    ::close(fd);  // nobody takes it again: its owner is gone
    return free;
  }
  // No lock to judge by (a folder killed before its lock file appeared): only a pid of this namespace says.
  return self.pidns != "unknown" && owner.pidns == self.pidns && owner.pid > 0 &&
         ::kill(static_cast<pid_t>(owner.pid), 0) != 0 && errno == ESRCH;
}

bool lockExclusively(int fd) {
  int r;
  do r = ::flock(fd, LOCK_EX | LOCK_NB);
  while (r != 0 && errno == EINTR);
  return r == 0;
}

int createFolderLock(const std::string& folder) {
  const fs::path final_name = fs::path(folder) / kStagingLockName;
  const fs::path early_name = fs::path(folder) / (std::string(kStagingLockName) + ".new");
  const int fd = ::open(early_name.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (fd < 0) return -1;
  if (!lockExclusively(fd) || ::rename(early_name.c_str(), final_name.c_str()) != 0) {
    const int saved = errno;
    ::close(fd);
    ::unlink(early_name.c_str());
    errno = saved;
    return -1;
  }
  return fd;
}

}  // namespace onetip
