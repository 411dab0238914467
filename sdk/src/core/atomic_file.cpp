#include "core/atomic_file.hpp"

#include <ext/stdio_filebuf.h>
#include <fcntl.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <vector>

#include "core/error.hpp"
#include "core/staging_owner.hpp"

namespace onetip {

namespace fs = std::filesystem;

namespace {

// A file buffer that remembers the errno of its first failed write: a stream
// that went bad while writing a row says why only through this.
class ErrnoFilebuf : public __gnu_cxx::stdio_filebuf<char> {
 public:
  using __gnu_cxx::stdio_filebuf<char>::stdio_filebuf;
  int error = 0;

 protected:
  int_type overflow(int_type c) override {
    const int_type r = stdio_filebuf::overflow(c);
    if (traits_type::eq_int_type(r, traits_type::eof())) remember();
    return r;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    const std::streamsize r = stdio_filebuf::xsputn(s, n);
    if (r < n) remember();
    return r;
  }
  int sync() override {
    const int r = stdio_filebuf::sync();
    if (r != 0) remember();
    return r;
  }

 private:
  void remember() {
    if (error == 0) error = errno != 0 ? errno : EIO;
  }
};

}  // namespace

struct AtomicFile::Staging {
  std::string path;
  int fd = -1;
  std::unique_ptr<ErrnoFilebuf> buffer;
  std::unique_ptr<std::ostream> out;
  off_t flushed = 0;         // bytes up to the last successful flush(): whole rows
  bool failed = false;       // the last flush() failed; the file is cut back to `flushed` before anything else
  bool retryable = false;    // and everything after `flushed` was still in the buffer (no write of the buffer's own)
  std::string failure;       // its message
};

namespace {

const char* const kDiscardedInfix = ".tmp.";
const char* const kKeptInfix = ".partial.";

// "<target><infix><owner tag>.XXXXXX" plus `suffix`: the template of mkstemp and mkdtemp.
std::string stagingTemplate(const std::string& target, const char* infix, const char* suffix = "") {
  return target + infix + stagingOwnerTag() + ".XXXXXX" + suffix;
}

mode_t currentUmask() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return mask;
}

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

std::vector<std::string> abandonedStaging(const std::string& target, bool kept_recordings) {
  const fs::path t(target);
  const fs::path folder = t.has_parent_path() ? t.parent_path() : fs::path(".");
  const std::string prefix = t.filename().string() + (kept_recordings ? kKeptInfix : kDiscardedInfix);
  std::error_code ec;
  std::vector<std::string> found;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    const auto owner = parseStagingOwner(name.substr(prefix.size()));
    if (owner && stagingAbandoned(entry.path(), *owner)) found.push_back(entry.path().string());
  }
  return found;
}

void removeStaleStaging(const std::string& target) {
  std::error_code ec;
  for (const auto& p : abandonedStaging(target, false)) fs::remove_all(p, ec);  // a symlink is removed, never followed
}

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)), staging_(std::make_unique<Staging>()) {
  requireRegularFileTarget(path_);
  removeStaleStaging(path_);
  // Made under a name ending in '~' (which no cleaner matches), locked, then renamed to its staging
  // name: a staging name never shows a file whose lock is not held yet.
  std::string early = stagingTemplate(path_, kDiscardedInfix, "~");
  const int fd = ::mkostemps(early.data(), 1, O_CLOEXEC);
  if (fd < 0) throw InputError(path_ + ": cannot create a file beside it (" + std::strerror(errno) + ")");
  const std::string name = early.substr(0, early.size() - 1);
  if (!lockExclusively(fd) || ::rename(early.c_str(), name.c_str()) != 0) {
    const int saved = errno;
    ::close(fd);
    ::unlink(early.c_str());
    throw InputError(path_ + ": cannot stage a file beside it (" + std::strerror(saved) + ")");
  }
  ::fchmod(fd, 0666 & ~currentUmask());
  staging_->path = name;
  staging_->fd = fd;
  staging_->buffer = std::make_unique<ErrnoFilebuf>(fd, std::ios::out | std::ios::binary);
  staging_->out = std::make_unique<std::ostream>(staging_->buffer.get());
}

AtomicFile::~AtomicFile() {
  if (committed_ || !staging_->out) return;  // committed, or discarded
  staging_->out.reset();
  staging_->buffer.reset();  // closes the descriptor
  ::unlink(staging_->path.c_str());
}

std::ostream& AtomicFile::stream() { return *staging_->out; }

void AtomicFile::flush() {
  if (committed_ || !staging_->out) return;
  Staging& st = *staging_;
  if (st.failed) {
    if (!st.retryable) throw InputError(st.failure);
    // Cut what the failed write left and write the buffer again (the space may have come free).
    if (::ftruncate(st.fd, st.flushed) != 0 || ::lseek(st.fd, st.flushed, SEEK_SET) != st.flushed)
      throw InputError(st.failure);
    st.out->clear();
    st.buffer->error = 0;
  }
  // The record can be written again only if all of it is still in the buffer: nothing of it was written
  // (or failed to be, dropping what the stream then refused) before this flush.
  st.retryable = ::lseek(st.fd, 0, SEEK_CUR) == st.flushed && st.buffer->error == 0 && *st.out;
  errno = 0;
  st.out->flush();
  const int error = st.buffer->error != 0 ? st.buffer->error : errno != 0 ? errno : EIO;
  const off_t at = ::lseek(st.fd, 0, SEEK_CUR);
  st.failed = !*st.out || at < 0;
  if (!st.failed) {
    st.flushed = at;
    return;
  }
  st.failure = path_ + ": write failed (" + std::strerror(error) + ")";
  throw InputError(st.failure);
}

void AtomicFile::commitFlushed() {
  if (committed_) throw InputError(path_ + ": already committed");
  Staging& st = *staging_;
  if (!st.out || st.flushed == 0) throw InputError(path_ + ": nothing was written whole");
  const int fd = ::dup(st.fd);  // outlives the buffer, whose close may still write what is pending
  st.out.reset();
  st.buffer.reset();
  const bool cut = fd >= 0 && ::ftruncate(fd, st.flushed) == 0;
  const int error = errno;
  if (fd >= 0) ::close(fd);
  if (!cut) throw InputError(path_ + ": cannot cut back to its last whole row (" + std::strerror(error) + ")");
  requireRegularFileTarget(path_);
  if (::rename(st.path.c_str(), path_.c_str()) != 0)
    throw InputError(path_ + ": cannot move into place: " + std::strerror(errno));
  committed_ = true;
}

void AtomicFile::discard() {
  if (committed_ || !staging_->out) return;
  ::unlink(staging_->path.c_str());  // first: what is still pending goes into a file that no longer lasts
  staging_->out.reset();
  staging_->buffer.reset();  // closes the descriptor, freeing the space
}

void AtomicFile::commit() {
  if (committed_) throw InputError(path_ + ": already committed");
  if (!staging_->out) throw InputError(path_ + ": discarded");
  std::ostream& out = *staging_->out;
  errno = 0;
  out.flush();
  const bool flushed = static_cast<bool>(out);
  const int flush_error = staging_->buffer->error != 0 ? staging_->buffer->error : errno;
  const bool written = flushed && staging_->buffer->close() != nullptr;
  const int error = flushed ? errno : flush_error;
  if (!written) throw InputError(path_ + ": write failed (" + std::strerror(error != 0 ? error : EIO) + ")");
  requireRegularFileTarget(path_);  // what the target is now, not what it was at the start
  if (::rename(staging_->path.c_str(), path_.c_str()) != 0)
    throw InputError(path_ + ": cannot move into place: " + std::strerror(errno));
  committed_ = true;
}

AtomicDir::AtomicDir(const std::string& target, Abandoned abandoned) : abandoned_(abandoned) {
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
  std::string name = stagingTemplate(target_, abandoned == Abandoned::keep ? kKeptInfix : kDiscardedInfix);
  if (!::mkdtemp(name.data())) throw InputError(target + ": cannot create a folder beside it (" + std::strerror(errno) + ")");
  staging_ = name;
  lock_fd_ = createFolderLock(staging_);
  if (lock_fd_ < 0) {
    const int saved = errno;
    fs::remove_all(staging_, ec);
    throw InputError(staging_ + ": cannot lock the staging folder (" + std::strerror(saved) + ")");
  }
  ::chmod(staging_.c_str(), 0777 & ~currentUmask());
}

AtomicDir::~AtomicDir() {
  if (!committed_ && abandoned_ == Abandoned::remove) {
    std::error_code ec;
    fs::remove_all(staging_, ec);
  }
  ::close(lock_fd_);  // the lock goes: a kept folder is now judged abandoned
}

void AtomicDir::discard() {
  if (committed_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
  abandoned_ = Abandoned::remove;
}

void AtomicDir::commit() {
  // rename() replaces an empty folder at most: one that filled meanwhile makes it fail
  if (::rename(staging_.c_str(), target_.c_str()) != 0)
    throw InputError(target_ + ": cannot move the output into place (" + std::strerror(errno) + ")");
  committed_ = true;
  ::unlink((fs::path(target_) / kStagingLockName).c_str());  // still locked until the descriptor closes
}

}  // namespace onetip
