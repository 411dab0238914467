#include "capture/frame_source.hpp"

namespace onetip::capture {

const char* toString(FrameStatus s) noexcept {
  switch (s) {
    case FrameStatus::ok: return "ok";
    case FrameStatus::skipped: return "skipped";
    case FrameStatus::error: return "error";
    case FrameStatus::end: break;
  }
  return "end";
}

Frame FrameSource::count(Frame f) {
  switch (f.status) {
    case FrameStatus::ok: ++counters_.delivered; break;
    case FrameStatus::skipped: ++counters_.skipped; break;
    case FrameStatus::error: ++counters_.errors; break;
    case FrameStatus::end: break;
  }
  return f;
}

Frame FrameSource::deliver(Frame f, cv::Mat grey, const std::optional<std::string>& problem,
                           const std::string& where) {
  if (problem) {
    f.status = FrameStatus::skipped;
    f.encoded.clear();
    f.message = where + ": " + *problem;
  } else {
    f.status = FrameStatus::ok;
    f.grey = std::move(grey);
  }
  return count(std::move(f));
}

}  // namespace onetip::capture
