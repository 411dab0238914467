// core/atomic_file.hpp — outputs that are whole or absent, never half-written,
// and never written through someone else's file.
//
// AtomicFile writes to a staging file beside the target and renames it over
// the target in commit(); if the object is destroyed without commit() (an
// error, an exception, an interrupt that unwinds) the staging file is removed
// and the target is untouched.
//   * The target must be absent or a regular file: a device (/dev/null), a
//     folder, a socket or a FIFO is refused (following symlinks to see what a
//     link points at; a link itself is replaced, its target never written).
//   * The staging file "<target>.tmp.<pid>.<random>" is created with mkstemp
//     (O_CREAT|O_EXCL, mode 0600 then the umask's regular mode): never opened
//     through a planted symlink or over an existing file, written through that
//     descriptor only.
//   * Staging files of killed runs ("<target>.tmp.<pid>[.*]" whose process no
//     longer exists) are removed when the next AtomicFile for the same target opens.
#pragma once

#include <memory>
#include <ostream>
#include <string>

namespace onetip {

class AtomicFile {
 public:
  // Throws InputError when the target is not a regular file or the folder is not writable.
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream();
  const std::string& path() const { return path_; }
  // Flushes, closes and renames into place; throws InputError on I/O failure.
  void commit();

 private:
  struct Staging;
  std::string path_;
  std::unique_ptr<Staging> staging_;
  bool committed_ = false;
};

// A folder that appears whole or not at all: filled under a fresh staging
// folder "<target>.tmp.<pid>.<random>" (mkdtemp, then the umask's mode) and
// renamed to the target in commit(); removed with its content if never
// committed. The target must be absent or an empty folder: nothing the run
// did not create is ever deleted or replaced ("out/" is "out"; "." and ".."
// are refused). Stale staging folders of killed runs are removed first.
class AtomicDir {
 public:
  explicit AtomicDir(const std::string& target);  // throws InputError
  ~AtomicDir();
  AtomicDir(const AtomicDir&) = delete;
  AtomicDir& operator=(const AtomicDir&) = delete;

  const std::string& path() const { return staging_; }  // where to write
  void commit();  // renames into place; throws InputError (e.g. the target filled meanwhile)

 private:
  std::string target_;
  std::string staging_;
  bool committed_ = false;
};

// Throws InputError unless `path` is absent or (after symlinks) a regular file.
void requireRegularFileTarget(const std::string& path);
// Why `path` cannot be read as a file, or "" when it is a regular file (after
// symlinks): "no such file", "is a directory, not a file", or "is not a
// regular file (a device, socket or FIFO)". A folder opens as an ifstream and
// reports a size of 2^63 - 1 bytes; callers check here first and say so.
std::string inputFileProblem(const std::string& path);
// Throws InputError "<path>: <inputFileProblem>" unless `path` is a readable regular file.
void requireInputFile(const std::string& path);
// Removes "<target>.tmp.<pid>" and "<target>.tmp.<pid>.*" entries beside `target`
// (files, or folders such as the simulator's staging folder) whose process is gone.
void removeStaleStaging(const std::string& target);

}  // namespace onetip
