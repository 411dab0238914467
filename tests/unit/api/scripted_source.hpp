// A FrameSource for pipeline tests: hands out a fixed list of frames (or
// errors), optionally blocking inside next() until released, to exercise the
// threads without a camera.
#pragma once

#include <condition_variable>
#include <memory>
#include <mutex>
#include <vector>

#include "capture/frame_source.hpp"

namespace onetip::test {

// Opens or closes a door that next() waits at.
struct Gate {
  std::mutex mutex;
  std::condition_variable cv;
  bool open = false;
  int waiting = 0;  // threads blocked at the gate
  void release();
};

class ScriptedSource : public capture::FrameSource {
 public:
  // `frames`: what next() returns in turn, then `end`. With a gate, every
  // next() first waits until the gate is open.
  explicit ScriptedSource(std::vector<capture::Frame> frames, std::shared_ptr<Gate> gate = nullptr);
  capture::Frame next() override;
  std::string describe() const override { return "scripted"; }

 private:
  std::vector<capture::Frame> frames_;
  std::size_t next_ = 0;
  std::shared_ptr<Gate> gate_;
};

// `count` frames of `grey`, indices 0.., timestamps index / 30 s.
std::vector<capture::Frame> repeatedFrames(const cv::Mat& grey, int count);

}  // namespace onetip::test
