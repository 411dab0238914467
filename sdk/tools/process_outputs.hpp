// tools/process_outputs.hpp — `onetip process`'s files (pose.csv, and
// markers.csv and timing.csv when asked for) on a full disk (issue 39: the
// error came with no cause after the whole input, and pose.csv was lost
// because markers.csv had used the space).
//   * Each file is flushed at the end of every frame: a write error is known
//     at that frame, named with its cause ("No space left on device"), and
//     processing stops there.
//   * pose.csv comes first: when it is the file that cannot be written, the
//     other outputs are dropped to give it their space, and it is written again.
//   * What was written whole is kept: each remaining file up to its last whole
//     frame (AtomicFile::commitFlushed), so nothing half-written ever appears.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "core/csv_table.hpp"

namespace onetip::tools {

class ProcessOutputs {
 public:
  ProcessOutputs(const std::string& pose, const std::optional<std::string>& markers,
                 const std::optional<std::string>& timing);

  CsvWriter& pose() { return *files_[0]; }
  CsvWriter* markers() { return files_[1].get(); }
  CsvWriter* timing() { return files_[2].get(); }

  // After a frame's rows: true, or false once a write failed (failure() names it; stop processing).
  bool endFrame();
  const std::string& failure() const noexcept { return failure_; }
  // Commits every file; after a failure, what is whole, printing what was kept and dropped to stderr.
  void commit();

 private:
  std::unique_ptr<CsvWriter> files_[3];
  int failed_ = -1;  // index in files_ of the file whose write failed
  std::string failure_;
};

}  // namespace onetip::tools
