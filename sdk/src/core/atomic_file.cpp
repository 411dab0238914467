#include "core/atomic_file.hpp"

#include <ext/stdio_filebuf.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <vector>

#include "core/error.hpp"

namespace onetip {

namespace fs = std::filesystem;

struct AtomicFile::Staging {
  std::string path;
  int fd = -1;
  std::unique_ptr<__gnu_cxx::stdio_filebuf<char>> buffer;
  std::unique_ptr<std::ostream> out;
};

namespace {

// The pid in "<name>.tmp.<pid>" or "<name>.tmp.<pid>.<anything>", or -1.
long stagingPid(const std::string& entry, const std::string& prefix) {
  if (entry.compare(0, prefix.size(), prefix) != 0) return -1;
  const std::string rest = entry.substr(prefix.size());
  const size_t end = rest.find('.');
  const std::string digits = rest.substr(0, end);
  if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) return -1;
  return std::stol(digits);
}

bool processGone(long pid) { return pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH; }

}  // namespace

void requireRegularFileTarget(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return;  // absent (or a dangling link, replaced by the rename)
  if (!S_ISREG(st.st_mode))
    throw InputError(path + ": exists and is not a regular file (a device, folder, socket or FIFO); refusing to "
                            "replace it");
}

std::string inputFileProblem(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    return errno == ENOENT || errno == ENOTDIR ? "no such file"
                                               : std::string("cannot read (") + std::strerror(errno) + ")";
  if (S_ISDIR(st.st_mode)) return "is a directory, not a file";
  if (!S_ISREG(st.st_mode)) return "is not a regular file (a device, socket or FIFO)";
  return "";
}

void requireInputFile(const std::string& path) {
  const std::string problem = inputFileProblem(path);
  if (!problem.empty()) throw InputError(path + ": " + problem);
}

void removeStaleStaging(const std::string& target) {
  const fs::path t(target);
  const fs::path folder = t.has_parent_path() ? t.parent_path() : fs::path(".");
  const std::string prefix = t.filename().string() + ".tmp.";
  std::error_code ec;
  std::vector<fs::path> stale;
  for (const auto& entry : fs::directory_iterator(folder, ec))
    if (processGone(stagingPid(entry.path().filename().string(), prefix))) stale.push_back(entry.path());
  for (const auto& p : stale) fs::remove_all(p, ec);  // a symlink is removed, never followed
}

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)), staging_(std::make_unique<Staging>()) {
  requireRegularFileTarget(path_);
  removeStaleStaging(path_);
  std::string name = path_ + ".tmp." + std::to_string(::getpid()) + ".XXXXXX";
  std::vector<char> buf(name.begin(), name.end());
  buf.push_back('\0');
  const int fd = ::mkstemp(buf.data());
  if (fd < 0) throw InputError(path_ + ": cannot create a file beside it (" + std::strerror(errno) + ")");
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  staging_->path = buf.data();
  staging_->fd = fd;
  staging_->buffer = std::make_unique<__gnu_cxx::stdio_filebuf<char>>(fd, std::ios::out | std::ios::binary);
  staging_->out = std::make_unique<std::ostream>(staging_->buffer.get());
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  staging_->out.reset();
  staging_->buffer.reset();  // closes the descriptor
  ::unlink(staging_->path.c_str());
}

std::ostream& AtomicFile::stream() { return *staging_->out; }

void AtomicFile::commit() {
  if (committed_) throw InputError(path_ + ": already committed");
  std::ostream& out = *staging_->out;
  out.flush();
  const bool written = static_cast<bool>(out) && staging_->buffer->close() != nullptr;
  if (!written) throw InputError(path_ + ": write failed");
  requireRegularFileTarget(path_);  // what the target is now, not what it was at the start
  if (::rename(staging_->path.c_str(), path_.c_str()) != 0)
    throw InputError(path_ + ": cannot move into place: " + std::strerror(errno));
  committed_ = true;
}

AtomicDir::AtomicDir(const std::string& target) {
  fs::path t = fs::path(target).lexically_normal();
  if (!t.has_filename()) t = t.parent_path();  // "out/" is "out"
  if (t.empty() || t.filename() == "." || t.filename() == "..")
    throw InputError(target + ": name a new or empty folder to create (not . or ..)");
  target_ = t.string();
  std::error_code ec;
  if (fs::exists(t, ec) && !(fs::is_directory(t, ec) && fs::is_empty(t, ec)))
    throw InputError(target + ": exists and is not an empty folder; nothing is ever deleted or replaced: choose "
                              "another one or remove it");
  removeStaleStaging(target_);
  std::string name = target_ + ".tmp." + std::to_string(::getpid()) + ".XXXXXX";
  if (!::mkdtemp(name.data())) throw InputError(target + ": cannot create a folder beside it (" + std::strerror(errno) + ")");
  staging_ = name;
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::chmod(staging_.c_str(), 0777 & ~mask);
}

AtomicDir::~AtomicDir() {
  if (committed_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

void AtomicDir::commit() {
  // rename() replaces an empty folder at most: one that filled meanwhile makes it fail
  if (::rename(staging_.c_str(), target_.c_str()) != 0)
    throw InputError(target_ + ": cannot move the output into place (" + std::strerror(errno) + ")");
  committed_ = true;
}

}  // namespace onetip
