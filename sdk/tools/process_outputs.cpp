#include "process_outputs.hpp"

#include <cstdio>

#include "core/error.hpp"
#include "core/pose_csv.hpp"

namespace onetip::tools {

ProcessOutputs::ProcessOutputs(const std::string& pose, const std::optional<std::string>& markers,
                               const std::optional<std::string>& timing) {
  files_[0] = std::make_unique<CsvWriter>(pose, poseCsvHeader(true));
  if (markers) files_[1] = std::make_unique<CsvWriter>(*markers, std::vector<std::string>{"frame", "id", "x", "y", "z"});
  if (timing) files_[2] = std::make_unique<CsvWriter>(*timing, std::vector<std::string>{"frame", "stage", "ms"});
}

bool ProcessOutputs::endFrame() {
  if (failed_ >= 0) return false;
  for (int i = 0; i < 3; ++i) {
    if (!files_[i]) continue;
    try {
      files_[i]->flush();
    } catch (const InputError& e) {
      failed_ = i;
      failure_ = e.what();
      return false;
    }
  }
  return true;
}

void ProcessOutputs::commit() {
  if (failed_ < 0) {
    for (auto& f : files_)
      if (f) f->commit();
    return;
  }
  std::string kept, dropped;
  if (failed_ == 0) {  // pose.csv first: the others give it their space
    for (int i = 1; i < 3; ++i)
      if (files_[i]) {
        dropped += " " + files_[i]->path();
        files_[i]->discard();
        files_[i].reset();
      }
    try {
      files_[0]->flush();
    } catch (const InputError&) {  // still no room: its last whole frame is kept below
    }
  }
  for (auto& f : files_) {
    if (!f) continue;
    try {
      f->commitFlushed();
      kept += " " + f->path();
    } catch (const InputError& e) {
      std::fprintf(stderr, "onetip process: %s\n", e.what());
      dropped += " " + f->path();
    }
  }
  std::fprintf(stderr, "onetip process: %s; stopped there. Kept up to the last whole frame:%s%s%s\n",
               failure_.c_str(), kept.empty() ? " nothing" : kept.c_str(), dropped.empty() ? "" : "; not written:",
               dropped.c_str());
}

}  // namespace onetip::tools
