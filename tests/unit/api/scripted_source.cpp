#include "scripted_source.hpp"

namespace onetip::test {

void Gate::release() {
  {
    std::lock_guard lock(mutex);
    open = true;
  }
  cv.notify_all();
}

ScriptedSource::ScriptedSource(std::vector<capture::Frame> frames, std::shared_ptr<Gate> gate)
    : frames_(std::move(frames)), gate_(std::move(gate)) {}

capture::Frame ScriptedSource::next() {
  if (gate_) {
    std::unique_lock lock(gate_->mutex);
    ++gate_->waiting;
    gate_->cv.notify_all();
    gate_->cv.wait(lock, [&] { return gate_->open; });
  }
  if (next_ >= frames_.size()) return capture::Frame{};
  return count(frames_[next_++]);
}

std::vector<capture::Frame> repeatedFrames(const cv::Mat& grey, int count) {
  std::vector<capture::Frame> out;
  for (int i = 0; i < count; ++i) {
    capture::Frame f;
    f.status = capture::FrameStatus::ok;
    f.grey = grey;
    f.index = i;
    f.timestamp_s = i / 30.0;
    out.push_back(f);
  }
  return out;
}

}  // namespace onetip::test
