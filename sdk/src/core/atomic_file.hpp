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
//   * The staging file "<target>.tmp.<owner>.<random>" (core/staging_owner.hpp:
//     host, boot, PID namespace, pid) is created with mkstemp (O_CREAT|O_EXCL,
//     mode 0600 then the umask's regular mode): never opened through a planted
//     symlink or over an existing file, written through that descriptor only,
//     and flock-ed by its writer for as long as it lives.
//   * Staging files of killed runs (provably abandoned: staging_owner.hpp) are
//     removed when the next AtomicFile or AtomicDir for the same target opens;
//     nothing else is (another host's, a live container's, an older version's).
#pragma once

#include <memory>
#include <ostream>
#include <string>
#include <vector>

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
  // Flushes, closes and renames into place; throws InputError on I/O failure, naming the cause.
  void commit();
  // Hands what is buffered to the file now; throws InputError naming the cause (a full
  // disk: "No space left on device") so a writer learns of it at that row, not at the end.
  // Called at the end of each whole record (a frame's rows), it marks how far the file is
  // whole. After a failure, flush() tries the pending record again (the space may have come
  // free) if none of it had been written on its own, else throws the same error again.
  void flush();
  // Commits the file as it was at the last successful flush(), cutting what came after;
  // throws InputError when nothing was flushed yet.
  void commitFlushed();
  // Removes the staging file now (freeing its space); the target is untouched and commit() refused.
  void discard();

 private:
  struct Staging;
  std::string path_;
  std::unique_ptr<Staging> staging_;
  bool committed_ = false;
};

// What becomes of an AtomicDir's staging folder that is never committed.
enum class Abandoned {
  remove,  // "<target>.tmp.<owner>.<random>": removed by the destructor, or as stale by a later run
  keep,    // "<target>.partial.<owner>.<random>" (a recording): left in place, never removed automatically
};

// A folder that appears whole or not at all: filled under a fresh staging
// folder (mkdtemp, then the umask's mode; holding kStagingLockName, flock-ed
// while the object lives) and renamed to the target in commit(). The target
// must be absent or an empty folder: nothing the run did not create is ever
// deleted or replaced ("out/" is "out"; "." and ".." are refused). Stale
// staging folders of killed runs are removed first (Abandoned::remove ones).
class AtomicDir {
 public:
  explicit AtomicDir(const std::string& target, Abandoned abandoned = Abandoned::remove);  // throws InputError
  ~AtomicDir();
  AtomicDir(const AtomicDir&) = delete;
  AtomicDir& operator=(const AtomicDir&) = delete;

  const std::string& path() const { return staging_; }  // where to write
  void commit();  // renames into place; throws InputError (e.g. the target filled meanwhile)
  void discard();  // removes the staging folder now, whatever the policy (it holds nothing worth keeping)

 private:
  std::string target_;
  std::string staging_;
  Abandoned abandoned_;
  int lock_fd_ = -1;
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
// The provably abandoned staging entries beside `target`: the removable ones
// ("<target>.tmp.*"), or with kept_recordings the kept ones ("<target>.partial.*").
std::vector<std::string> abandonedStaging(const std::string& target, bool kept_recordings);
// Removes the abandoned "<target>.tmp.*" entries (files, or folders such as the simulator's).
void removeStaleStaging(const std::string& target);

}  // namespace onetip
