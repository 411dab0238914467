// core/atomic_file.hpp — outputs that are whole or absent, never half-written.
//
// AtomicFile writes to a temporary file beside the target and renames it over
// the target in commit(); if the object is destroyed without commit() (an
// error, an exception) the temporary is removed and the target is untouched.
#pragma once

#include <fstream>
#include <string>

namespace onetip {

class AtomicFile {
 public:
  // Opens "<path>.tmp.<pid>"; throws InputError when the folder is not writable.
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return out_; }
  const std::string& path() const { return path_; }
  const std::string& tempPath() const { return temp_; }
  // Flushes, closes and renames into place; throws InputError on I/O failure.
  void commit();

 private:
  std::string path_;
  std::string temp_;
  std::ofstream out_;
  bool committed_ = false;
};

// Commits `write_to_temp(temp_path)` atomically: for writers (cv::imwrite,
// cv::FileStorage) that want a file name rather than a stream.
template <typename WriteFn>
void writeFileAtomically(const std::string& path, WriteFn&& write_to_temp) {
  AtomicFile file(path);
  file.stream().close();
  write_to_temp(file.tempPath());
  file.commit();
}

}  // namespace onetip
