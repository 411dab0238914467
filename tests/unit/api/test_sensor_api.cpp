// The public C++ API end to end on the simulator: every frame's 6-D result
// through onetip::Sensor (two threads, lossless) equals the single-threaded
// FrameProcessor's on the same frames, also across a reZero() issued from a
// callback; events agree with the per-frame results; options survive YAML;
// bad input and wrong call order give onetip::Error of the right kind.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "onetip/onetip.hpp"
#include "pipeline/frame_processor.hpp"
#include "sim/sim_frame_source.hpp"
#include "test_paths.hpp"

namespace onetip {
namespace {

const std::string kScenario = std::string(onetip::test::sourceDir()) + "/samples/scenarios/press.yaml";

std::string tempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("onetip_api_" + std::to_string(::getpid()) + "_" + name)).string();
}

void expectSame(const Input6& a, const Input6& b, std::int64_t frame) {
  const auto x = a.asArray(), y = b.asArray();
  for (size_t k = 0; k < 6; ++k) EXPECT_EQ(x[k], y[k]) << "frame " << frame << " axis " << k;
}

TEST(SensorApi, EveryFrameEqualsTheSingleThreadedProcessorAcrossAReZero) {
  constexpr std::int64_t kRezeroAfter = 45;  // in contact (the press peaks at 2 s = frame 60)
  SensorOptions options;
  options.lossless = true;
  options.event_queue_capacity = 100000;
  Sensor sensor(onetip::SensorConfig("sim:" + kScenario, "", "", ""), options);
  std::map<std::int64_t, FrameResult> results;
  sensor.onFrame([&](const FrameResult& f) {
    results[f.frame] = f;
    if (f.frame == kRezeroAfter) sensor.reZero();  // allowed inside a callback; applies from the next frame
  });
  sensor.start();
  ASSERT_TRUE(sensor.waitFinished(240));
  EXPECT_FALSE(sensor.running());

  // The reference: the same frames through FrameProcessor on this thread.
  sim::SimFrameSource source(kScenario);
  pipeline::FrameProcessor plain(source.simulator().calibration(), source.simulator().pattern());
  pipeline::FrameProcessor rezeroed(source.simulator().calibration(), source.simulator().pattern());
  int compared = 0, differs_from_plain = 0;
  for (capture::Frame f = source.next(); f.ok(); f = source.next()) {
    if (f.index == kRezeroAfter + 1) rezeroed.rezero();
    const pipeline::FrameResult a = plain.process(f.grey, f.timestamp_s);
    const pipeline::FrameResult b = rezeroed.process(f.grey, f.timestamp_s);
    ASSERT_TRUE(results.count(f.index)) << "frame " << f.index << " missing";
    const FrameResult& r = results[f.index];
    EXPECT_EQ(static_cast<int>(r.status), static_cast<int>(b.status));
    EXPECT_EQ(r.contact, b.pose.contact) << f.index;
    expectSame(r.raw, b.pose.raw, f.index);
    expectSame(r.input, b.pose.input, f.index);
    EXPECT_EQ(r.rows * r.cols, static_cast<int>(r.markers.size()));
    int valid = 0;
    for (size_t id = 0; id < r.markers.size(); ++id) {
      EXPECT_EQ(r.markers[id].valid, b.markers.valid[id] != 0);
      if (r.markers[id].valid) {
        ++valid;
        EXPECT_EQ(r.markers[id].z, b.markers.position[id].z());
      }
    }
    EXPECT_EQ(valid, b.markers.validCount());
    differs_from_plain += std::abs(a.pose.raw.dz - b.pose.raw.dz) > 0.5 ? 1 : 0;
    ++compared;
  }
  EXPECT_EQ(compared, static_cast<int>(results.size()));
  EXPECT_GT(compared, 80);
  EXPECT_GT(differs_from_plain, 5);  // the re-zero really changed the output

  // Events: contact begins (again after the re-zero) and ends; input events
  // carry their frame's result.
  Event e;
  int begins = 0, ends = 0, inputs = 0, presses = 0;
  while (sensor.pollEvent(e)) {
    switch (e.type) {
      case EventType::contact_begin: ++begins; break;
      case EventType::contact_end: ++ends; break;
      case EventType::press: ++presses; break;
      case EventType::input:
        ++inputs;
        expectSame(e.input, results[e.frame].input, e.frame);
        EXPECT_EQ(e.arrival_s, results[e.frame].arrival_s);
        break;
      default: break;
    }
  }
  EXPECT_EQ(begins, 2);
  EXPECT_GE(ends, 1);
  EXPECT_GE(presses, 1);
  EXPECT_GT(inputs, 30);

  const SensorStats stats = sensor.stats();
  EXPECT_EQ(stats.frames_dropped, 0);
  EXPECT_EQ(stats.frames_processed, compared);
  std::vector<std::string> names;
  for (const auto& s : stats.stages) names.push_back(s.stage);
  EXPECT_EQ(names, (std::vector<std::string>{"capture", "queue", "detect", "track", "triangulate", "contact", "pose",
                                             "process", "delivery"}));
  EXPECT_GT(stats.stages[7].median_ms, 0);
  EXPECT_GE(stats.stages[7].p99_ms, stats.stages[7].median_ms);
  EXPECT_GE(stats.stages[8].median_ms, stats.stages[7].median_ms);  // delivery includes processing
}

TEST(SensorApi, OptionsRoundTripThroughYamlAndRejectTypos) {
  SensorOptions o;
  o.queue_capacity = 5;
  o.lossless = true;
  o.working_range = {3, 3, 2, 10, 30, 35};
  o.gain = {2, 2, 1, 1, 0.5, 0.5};
  o.filter = FilterKind::moving_average;
  o.filter_window = 7;
  o.press_mm = 2.0;
  const std::string path = tempPath("options.yaml");
  o.save(path);
  const SensorOptions back = SensorOptions::load(path);
  EXPECT_EQ(back.queue_capacity, 5);
  EXPECT_TRUE(back.lossless);
  EXPECT_EQ(back.working_range, o.working_range);
  EXPECT_EQ(back.gain, o.gain);
  EXPECT_EQ(back.filter, FilterKind::moving_average);
  EXPECT_EQ(back.filter_window, 7);
  EXPECT_EQ(back.press_mm, 2.0);

  std::ofstream(path) << "%YAML:1.0\nqueue_capacty: 3\n";
  try {
    SensorOptions::load(path);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::input);
    EXPECT_NE(std::string(e.what()).find("key 'queue_capacty': unknown key"), std::string::npos) << e.what();
  }
  std::ofstream(path) << "%YAML:1.0\nrelease_mm: 2.0\n";  // above press_mm (1.5)
  EXPECT_THROW(SensorOptions::load(path), Error);
  std::filesystem::remove(path);

  SensorOptions bad;
  bad.working_range[4] = -1;
  EXPECT_THROW(bad.validate(), Error);
}

TEST(SensorApi, BadInputAndWrongCallOrderGiveErrorsOfTheRightKind) {
  const auto kindOf = [](auto&& fn) {
    try {
      fn();
    } catch (const Error& e) {
      EXPECT_GT(std::string(e.what()).size(), 5u);
      return static_cast<int>(e.kind());
    }
    return -1;
  };
  EXPECT_EQ(kindOf([] { Sensor s(SensorConfig("sim:/no/such.yaml", "", "", "")); }), static_cast<int>(ErrorKind::input));
  EXPECT_EQ(kindOf([] { Sensor s(SensorConfig("", "", "", "")); }), static_cast<int>(ErrorKind::input));
  EXPECT_EQ(kindOf([] { Sensor s(SensorConfig(std::string(onetip::test::sourceDir()) + "/samples/scenarios", "", "", "")); }),
            static_cast<int>(ErrorKind::input));  // not a sim: source: calibration needed
  EXPECT_EQ(kindOf([] { Sensor s(SensorConfig("sim:" + kScenario, "/no/calib.yaml", "", "")); }),
            static_cast<int>(ErrorKind::input));  // calibration without pattern
  EXPECT_EQ(kindOf([] { Sensor s(SensorConfig("sim:" + kScenario, "", "", "/no/reference.png")); }),
            static_cast<int>(ErrorKind::input));
  SensorOptions bad;
  bad.stop_timeout_ms = 0;
  EXPECT_EQ(kindOf([&] { Sensor s(SensorConfig("sim:" + kScenario, "", "", ""), bad); }), static_cast<int>(ErrorKind::input));

  Sensor sensor(onetip::SensorConfig("sim:" + kScenario, "", "", ""));
  Event e;
  EXPECT_FALSE(sensor.waitEvent(e, 0.01));  // not started: nothing, no wait
  sensor.start();
  EXPECT_EQ(kindOf([&] { sensor.start(); }), static_cast<int>(ErrorKind::state));
  sensor.stop();
  sensor.stop();  // idempotent
  EXPECT_EQ(kindOf([&] { sensor.start(); }), static_cast<int>(ErrorKind::state));  // runs once
  // Issue 39: NaN is refused; an infinite or huge limit is no limit, never converted to a clock (UB).
  EXPECT_EQ(kindOf([&] { sensor.waitFinished(std::nan("")); }), static_cast<int>(ErrorKind::input));
  EXPECT_FALSE(sensor.waitFinished(HUGE_VAL));  // stopped, not finished: returns at once
  EXPECT_FALSE(sensor.waitFinished(1e300));

  Sensor never_started(onetip::SensorConfig("sim:" + kScenario, "", "", ""));
  never_started.stop();  // it never ran and never will: waiters return, start() is refused
  EXPECT_FALSE(never_started.waitFinished(-1));
  EXPECT_EQ(kindOf([&] { never_started.start(); }), static_cast<int>(ErrorKind::state));
}

TEST(SensorApi, JoystickAndSpnavScalingFollowTheDocumentedFormulas) {
  Input6 v;
  v.dx = 2;       // half of +4 mm
  v.dz = 1.5;     // middle of [0, 3]
  v.pitch = 20;   // half of +40 deg
  v.yaw = -15;    // the end of [-15, 15]
  const auto j = joystickAxes(v);
  EXPECT_EQ(j, (std::array<std::int32_t, 6>{16384, 0, 0, 16384, 0, -32767}));  // x y z rx ry rz
  const auto s = spnavAxes(v);
  EXPECT_EQ(s, (std::array<std::int32_t, 6>{175, 0, 175, 175, 0, -350}));  // v / max(|lo|, |hi|) * 350
}

}  // namespace
}  // namespace onetip
