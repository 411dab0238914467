// The threaded Pipeline's mechanics with scripted sources: the latest-frame-
// wins queue drops and counts stale frames (and never more than it must),
// lossless mode keeps every frame, stop() returns while the source is blocked
// inside a read, source errors become error events and end the stream, and
// callbacks that throw are contained.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "core/error.hpp"
#include "pipeline/pipeline.hpp"
#include "scripted_source.hpp"
#include "sim/simulator.hpp"
#include "test_paths.hpp"

namespace onetip::pipeline {
namespace {

using test::Gate;
using test::ScriptedSource;

struct Rig {
  StereoCalibration calib;
  MarkerPattern pattern;
  cv::Mat blank;  // right size, no markers: every frame fails to become the rest state (an error event)
};

const Rig& rig() {
  static const Rig r = [] {
    sim::Simulator s(sim::loadScenario(std::string(onetip::test::sourceDir()) + "/samples/scenarios/press.yaml"));
    Rig out{s.calibration(), s.pattern(), {}};
    out.blank = cv::Mat(out.calib.image_height, out.calib.image_width, CV_8UC1, cv::Scalar(128));
    return out;
  }();
  return r;
}

std::unique_ptr<Pipeline> makePipeline(std::unique_ptr<capture::FrameSource> source, PipelineOptions o) {
  return std::make_unique<Pipeline>(std::move(source), rig().calib, rig().pattern, o);
}

TEST(PipelineThreads, LatestFrameWinsDropsStaleFramesWhenProcessingIsSlow) {
  PipelineOptions o;
  o.queue_capacity = 2;
  auto p = makePipeline(std::make_unique<ScriptedSource>(test::repeatedFrames(rig().blank, 40)), o);
  std::vector<std::int64_t> frames;
  p->onEvent([&](const PipelineEvent& e) {
    frames.push_back(e.frame);
    std::this_thread::sleep_for(std::chrono::milliseconds(15));  // a slow consumer
  });
  p->start();
  ASSERT_TRUE(p->waitFinished(60));
  const PipelineStats s = p->stats();
  EXPECT_EQ(s.frames_captured, 40);
  EXPECT_GT(s.frames_dropped, 0);
  EXPECT_EQ(s.frames_processed + s.frames_dropped, 40);  // every frame processed or counted as dropped
  EXPECT_EQ(static_cast<std::int64_t>(frames.size()), s.frames_processed);
  EXPECT_TRUE(std::is_sorted(frames.begin(), frames.end()));
  EXPECT_EQ(frames.back(), 39);  // the newest frame always gets through
}

TEST(PipelineThreads, LosslessKeepsEveryFrameInOrder) {
  PipelineOptions o;
  o.queue_capacity = 1;
  o.lossless = true;
  auto p = makePipeline(std::make_unique<ScriptedSource>(test::repeatedFrames(rig().blank, 20)), o);
  std::vector<std::int64_t> frames;
  p->onFrame([&](const PipelineFrame& f) {
    frames.push_back(f.frame);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  });
  p->start();
  ASSERT_TRUE(p->waitFinished(60));
  EXPECT_EQ(p->stats().frames_dropped, 0);
  ASSERT_EQ(frames.size(), 20u);
  for (int i = 0; i < 20; ++i) EXPECT_EQ(frames[static_cast<size_t>(i)], i);
  // Frames that cannot be the rest state are reported, one error event each.
  PipelineEvent e;
  int errors = 0;
  while (p->pollEvent(e)) errors += e.event.type == input::EventType::error ? 1 : 0;
  EXPECT_EQ(errors, 20);
  EXPECT_FALSE(p->waitEvent(e, 5.0));  // finished and drained: returns at once
}

TEST(PipelineThreads, StopReturnsWhileTheSourceIsBlockedInARead) {
  auto gate = std::make_shared<Gate>();
  PipelineOptions o;
  o.stop_timeout_ms = 100;
  auto p = makePipeline(std::make_unique<ScriptedSource>(test::repeatedFrames(rig().blank, 3), gate), o);
  p->start();
  {
    std::unique_lock lock(gate->mutex);
    ASSERT_TRUE(gate->cv.wait_for(lock, std::chrono::seconds(10), [&] { return gate->waiting > 0; }));
  }
  const auto t0 = std::chrono::steady_clock::now();
  p->stop();
  const double stop_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(stop_s, 5.0);
  EXPECT_TRUE(p->stats().source_abandoned);
  EXPECT_FALSE(p->running());
  EXPECT_FALSE(p->finished());
  p.reset();        // the abandoned capture thread still owns the source
  gate->release();  // let it return and end
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
}

TEST(PipelineThreads, RepeatedSourceErrorsBecomeErrorEventsThenTheEnd) {
  std::vector<capture::Frame> script(5);
  for (auto& f : script) {
    f.status = capture::FrameStatus::error;
    f.message = "camera unplugged";
  }
  PipelineOptions o;
  o.max_consecutive_source_errors = 3;
  auto p = makePipeline(std::make_unique<ScriptedSource>(script), o);
  p->start();
  ASSERT_TRUE(p->waitFinished(10));
  std::vector<std::string> messages;
  PipelineEvent e;
  while (p->pollEvent(e)) {
    EXPECT_EQ(e.event.type, input::EventType::error);
    EXPECT_EQ(e.frame, -1);
    messages.push_back(e.event.message);
  }
  ASSERT_EQ(messages.size(), 3u);  // the fourth and fifth errors are never read
  EXPECT_NE(messages[0].find("camera unplugged"), std::string::npos);
  EXPECT_NE(messages[2].find("giving up"), std::string::npos);
  EXPECT_EQ(p->stats().source_errors, 3);
}

TEST(PipelineThreads, AThrowingCallbackIsContainedAndReported) {
  PipelineOptions o;
  o.lossless = true;
  auto p = makePipeline(std::make_unique<ScriptedSource>(test::repeatedFrames(rig().blank, 4)), o);
  p->onFrame([](const PipelineFrame&) { throw std::runtime_error("boom"); });
  p->start();
  ASSERT_TRUE(p->waitFinished(30));
  EXPECT_EQ(p->stats().callback_errors, 4);
  EXPECT_EQ(p->stats().frames_processed, 4);
  int reported = 0;
  PipelineEvent e;
  while (p->pollEvent(e)) reported += e.event.message.find("a callback threw: boom") != std::string::npos ? 1 : 0;
  EXPECT_EQ(reported, 4);
}

TEST(PipelineThreads, StartAndStopFromACallbackAreRefused) {
  PipelineOptions o;
  o.lossless = true;
  auto p = makePipeline(std::make_unique<ScriptedSource>(test::repeatedFrames(rig().blank, 2)), o);
  std::atomic<int> refused{0};
  p->onFrame([&](const PipelineFrame&) {
    try {
      p->stop();
    } catch (const PipelineStateError&) {
      ++refused;
    }
    p->onFrame({});  // replacing the running callback from inside it is allowed
  });
  p->start();
  EXPECT_THROW(p->start(), PipelineStateError);
  ASSERT_TRUE(p->waitFinished(30));
  EXPECT_EQ(refused.load(), 1);
  EXPECT_EQ(p->stats().callback_errors, 0);
}

TEST(PipelineThreads, InvalidOptionsNameTheField) {
  PipelineOptions o;
  o.queue_capacity = 0;
  try {
    makePipeline(std::make_unique<ScriptedSource>(std::vector<capture::Frame>{}), o);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("queue_capacity"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace onetip::pipeline
