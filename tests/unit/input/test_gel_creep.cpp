// A held press on a creeping gel is not a finger pressing deeper
// (input/gel_creep.hpp), on the simulator's viscoelastic pad against its
// ground truth: the markers tell the two apart, the held press reads the
// finger's depth once its creep has shown its time course, and a finger that
// presses deeper on an elastic pad with the creep's own time course is still
// read as depth.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "contact_events.hpp"
#include "input/gel_creep.hpp"
#include "sim_replay.hpp"
#include "test_paths.hpp"

using namespace onetip;
using namespace onetip::input;
using namespace onetip::poseval;

namespace {

constexpr double kNoiseMm = 0.0006;  // sim_replay.hpp's marker noise per axis

sim::Scenario worldScenario(const std::string& name) {
  return sim::loadScenario(std::string(test::sourceDir()) + "/tests/data/scenarios/world/" + name + ".yaml");
}

sim::Scenario creepPress() { return worldScenario("creep_press"); }

// The tracker's options for a recording: its pad's marker depth, as the pipeline takes it from the pattern.
PoseTrackerOptions optionsFor(const Recording& recording) {
  PoseTrackerOptions options;
  options.marker_depth_mm = recording.marker_depth_mm;
  return options;
}

// creep_press's finger on an elastic pad, pressing on from 1.5 mm after 1 s as the creep would sink the
// markers: depth 1.5 + 0.4 (1 - exp(-(t - 1) / tau_c)) mm, one keyframe per frame, tau_c the gel's.
sim::Scenario deeperOnAnElasticPad() {
  sim::Scenario s = creepPress();
  const double tau_c = s.world.viscoelastic.retardationTime();
  s.world.viscoelastic.relaxation = 0;
  auto& keys = s.indenters[0].keyframes;
  keys.resize(3);  // approach, touch, 1.5 mm at 1 s
  for (int k = 31; k <= 150; ++k) {
    sim::Keyframe key;
    key.t = k / s.fps;
    key.depth = 1.5 + 0.4 * (1 - std::exp(-(key.t - 1.0) / tau_c));
    keys.push_back(key);
  }
  sim::Keyframe up;
  up.t = 5.2;
  up.depth = -0.3;
  keys.push_back(up);
  up.t = 9.0;
  keys.push_back(up);
  return s;
}

// The marker fields u = p - rest (S, mm) as the tracker is given them (sim_replay.hpp's noise), frame by frame.
std::vector<std::vector<Eigen::Vector3d>> measuredFields(const sim::Scenario& scenario) {
  const Recording recording = record(scenario);
  std::vector<std::vector<Eigen::Vector3d>> u;
  for (const MarkerField& f : recording.frames) {
    u.emplace_back(f.position.size());
    for (size_t i = 0; i < u.back().size(); ++i) u.back()[i] = f.position[i] - recording.rest.position[i];
  }
  return u;
}

}  // namespace

TEST(GelCreep, TheMarkersTellAHeldCreepFromAFingerPressingDeeper) {
  // The same finger, the same time course after 1 s (frame 30): a creeping gel under the finger held from
  // there moves the markers along one straight line by exponentially shrinking increments; an elastic gel under
  // the finger pressing on moves them along a curve (the contact widens). From the frame the finger stopped,
  // windows of 2m frames: the creep's stay on one exponential within the noise bound, the deeper press's do
  // not, and the frame before the creep's is far off it (the finger stopped there).
  const auto creep = measuredFields(creepPress());
  const auto deeper = measuredFields(deeperOnAnElasticPad());
  const std::vector<std::uint8_t> all(creep[0].size(), 1);
  for (size_t m : {4, 8, 16, 32}) {
    const CreepWindow c = creepWindow(creep, 30, m, all, kNoiseMm, GelCreepOptions{}.fit_sigmas, 1e-3);
    const CreepWindow d = creepWindow(deeper, 30, m, all, kNoiseMm, GelCreepOptions{}.fit_sigmas, 1e-3);
    ASSERT_TRUE(c.shrinking && d.shrinking) << "m " << m;  // both decay: the time course alone does not tell
    const double bound = noiseMaximum(c.markers * static_cast<int>(2 * m - 1), 1e-3);
    EXPECT_TRUE(c.exponential) << "m " << m;
    EXPECT_LT(c.worst_sigmas, bound) << "m " << m;
    EXPECT_FALSE(d.exponential) << "m " << m;
    EXPECT_GT(d.worst_sigmas, bound) << "m " << m;
    EXPECT_EQ(c.start, 30u) << "m " << m;
    EXPECT_GT(c.before_sigmas, GelCreepOptions{}.stop_factor * GelCreepOptions{}.fit_sigmas) << "m " << m;
  }
  // Later in the deeper press the depth changes too little within a window for its curve to show: its window
  // is an exponential within the noise too, but it has no frame where a finger stopped before it.
  const CreepWindow tail = creepWindow(deeper, 45, 8, all, kNoiseMm, GelCreepOptions{}.fit_sigmas, 1e-3);
  EXPECT_TRUE(tail.exponential);
  EXPECT_LT(tail.worst_sigmas, noiseMaximum(tail.markers * 15, 1e-3));
  EXPECT_LT(tail.before_sigmas, GelCreepOptions{}.stop_factor * GelCreepOptions{}.fit_sigmas);
}

TEST(GelCreep, AHeldPressReadsTheFingersDepthOnceItsCreepIsMeasured) {
  // 1.5 mm held 4 s on a gel relaxing 30 % (tau 1 s): tau_c = 1.43 s, c = 0.43. Before, dz read 1.75 mm after
  // 2 s of holding where the truth is 1.375 (the creep as depth).
  const sim::Scenario scenario = creepPress();
  const Recording recording = record(scenario);
  PoseTracker tracker(optionsFor(recording));
  double measured_at = -1;
  double worst_after = 0;
  for (size_t k = 0; k < recording.frames.size(); ++k) {
    const TrackerResult r = tracker.update(recording.frames[k], recording.rest, recording.truth[k].t);
    if (measured_at < 0 && tracker.gelCreep().measured()) measured_at = r.t;
    const double t = recording.truth[k].t;
    if (measured_at >= 0 && t > measured_at && t <= 5.0 && recording.truth[k].in_contact)
      worst_after = std::max(worst_after, std::abs(r.raw.dz - recording.truth[k].input.dz));
  }
  // The constants depend on which window first passes, which the noise's last bits decide: the GCC release
  // build measures tau_c 1.480 s and c 0.439, the Clang sanitizer build 1.225 s and 0.386 (gel: 1.429, 0.429),
  // and the depth after the measurement within 0.026 and 0.060 mm of the truth.
  const sim::ViscoelasticOptions& gel = scenario.world.viscoelastic;
  EXPECT_NEAR(tracker.gelCreep().tau_c_s, gel.retardationTime(), 0.2 * gel.retardationTime());
  EXPECT_NEAR(tracker.gelCreep().gain, gel.creepGain(), 0.15 * gel.creepGain());
  // Measured within half a second of holding (the hold begins at 1 s), and from then on the depth is the finger's.
  EXPECT_GT(measured_at, 1.0);
  EXPECT_LT(measured_at, 1.5);
  EXPECT_LT(worst_after, 0.08);
  // Without the unit the creep is read as depth.
  ReplayOptions off;
  off.tracker.creep.enabled = false;
  const std::vector<ReplayFrame> before = replay(scenario, off);
  EXPECT_GT(before[90].raw.dz - before[90].gt.dz, 0.3);
}

TEST(GelCreep, TheMeasuredGelIsReportedOnceInTheTermsOfItsDatasheet) {
  // A user sees the gel measured where it happens (tools/sensor_notices.hpp prints it): one error event, in
  // the frame the creep became known, naming the relaxed fraction r = c / (1 + c) and the relaxation time
  // tau_c (1 - r), the simulator's own `viscoelastic` terms (creep_press: r 0.3, tau 1 s).
  const sim::Scenario scenario = creepPress();
  const Recording recording = record(scenario);
  PoseTracker tracker(optionsFor(recording));
  int notices = 0;
  double percent = -1, tau_s = -1;
  bool known_before = false, named_when_known = false;
  for (size_t k = 0; k < recording.frames.size(); ++k) {
    const TrackerResult r = tracker.update(recording.frames[k], recording.rest, recording.truth[k].t);
    for (const InputEvent& e : r.events) {
      if (e.type != EventType::error || e.message.find("creep measured") == std::string::npos) continue;
      ++notices;
      named_when_known = tracker.gelCreep().measured() && !known_before;
      ASSERT_EQ(std::sscanf(e.message.c_str(), "the gel's creep measured: %lf %% of its modulus relaxes, "
                                                "relaxation time %lf s", &percent, &tau_s), 2) << e.message;
    }
    known_before = tracker.gelCreep().measured();
  }
  EXPECT_EQ(notices, 1);
  EXPECT_TRUE(named_when_known);
  const sim::ViscoelasticOptions& gel = scenario.world.viscoelastic;
  // The message's figures are the model's, rounded: r to a percent, tau to 10 ms.
  EXPECT_NEAR(percent, 100 * tracker.gelCreep().relaxedFraction(), 0.5);
  EXPECT_NEAR(tau_s, tracker.gelCreep().relaxationTime(), 0.005);
  // And the gel's within the accuracy the test above allows its constants (r within 0.05, tau within 25 %).
  EXPECT_NEAR(percent / 100, gel.relaxation, 0.05);
  EXPECT_NEAR(tau_s, gel.time_s, 0.25 * gel.time_s);
}

TEST(GelCreep, APressOnAGelWhoseCreepIsKnownReadsItsDepthWhileHeld) {
  // creep_repress: the first press (held 2 s) measures the gel; the second, begun 0.3 s after the first lift-off
  // with the surface still 0.5 mm from rest, is held 0.3 s at 1 mm (before: 0.958 mm after 0.3 s against 0.867).
  const std::vector<ReplayFrame> frames =
      replay(sim::loadScenario(std::string(test::sourceDir()) + "/tests/data/scenarios/world/creep_repress.yaml"));
  int held = 0;
  for (const ReplayFrame& f : frames) {
    if (f.t < 4.0 || f.t > 4.3) continue;
    ASSERT_TRUE(f.gt_contact && f.contact) << "t " << f.t;
    EXPECT_NEAR(f.raw.dz, f.gt.dz, 0.05) << "t " << f.t;
    ++held;
  }
  EXPECT_GE(held, 9);
}

TEST(GelCreep, AFingerPressingDeeperOnAnElasticPadIsStillDepth) {
  // The twin: the finger itself goes 0.4 mm deeper with the creep's time course; nothing is taken away.
  const sim::Scenario scenario = deeperOnAnElasticPad();
  ReplayOptions off;
  off.tracker.creep.enabled = false;
  const std::vector<ReplayFrame> with = replay(scenario), without = replay(scenario, off);
  ASSERT_EQ(with.size(), without.size());
  EXPECT_GT(with[150].gt.dz - with[30].gt.dz, 0.35);
  for (size_t k = 0; k < with.size(); ++k) {
    EXPECT_EQ(with[k].raw.dz, without[k].raw.dz) << "frame " << k;
    if (with[k].gt_contact && with[k].t >= 1.0 && with[k].t <= 5.0) {
      EXPECT_NEAR(with[k].raw.dz, with[k].gt.dz, 0.05) << "frame " << k;
    }
  }
}

TEST(GelCreep, ARecoveryMeasuresTheGelAndTheNextLiftOffEndsOnTime) {
  // creep_unheld: two presses that never hold still, so no held press measures the gel. The decay after the
  // first finger's field went does (u_k = a u_{k-1}), in the frame that ends the first contact: from then on the
  // markers lose the gel's delayed part, and the second contact ends where the finger's own field goes below
  // the contact threshold, as the truth's contact rule says, not when the gel has recovered.
  const sim::Scenario scenario = worldScenario("creep_unheld");
  const Recording recording = record(scenario);
  PoseTracker tracker(optionsFor(recording));
  std::vector<int> true_ends, ends;
  bool last_truth = false, last = false, measured_in_first = false;
  double worst_dz_second = 0;
  for (size_t k = 0; k < recording.frames.size(); ++k) {
    const TrackerResult r = tracker.update(recording.frames[k], recording.rest, recording.truth[k].t);
    const sim::GroundTruthFrame& truth = recording.truth[k];
    if (last_truth && !truth.in_contact) true_ends.push_back(static_cast<int>(k));
    if (last && !r.contact) ends.push_back(static_cast<int>(k));
    if (true_ends.empty() && tracker.gelCreep().measured()) measured_in_first = true;
    if (truth.t > 2.5 && truth.t <= 3.7 && truth.in_contact && r.contact)  // the second press, to its lift
      worst_dz_second = std::max(worst_dz_second, std::abs(r.raw.dz - truth.input.dz));
    last_truth = truth.in_contact;
    last = r.contact;
  }
  const sim::ViscoelasticOptions& gel = scenario.world.viscoelastic;
  ASSERT_FALSE(measured_in_first);  // no hold: the first press measures nothing
  ASSERT_TRUE(tracker.gelCreep().measured());
  // The release build measures tau_c 1.446 s and c 0.432 (gel: 1.429, 0.429).
  EXPECT_NEAR(tracker.gelCreep().tau_c_s, gel.retardationTime(), 0.1 * gel.retardationTime());
  EXPECT_NEAR(tracker.gelCreep().gain, gel.creepGain(), 0.1 * gel.creepGain());
  ASSERT_EQ(true_ends.size(), 2u);
  ASSERT_EQ(ends.size(), 2u);
  for (int i : {0, 1})
    EXPECT_LE(std::abs(ends[i] - true_ends[i]), 2) << "truth " << true_ends[i] << ", tracker " << ends[i];
  // The second press, begun while the gel still recovers, reads its depth (issue 38: within 0.05 mm; 0.008 mm
  // here, and 0.063 mm with the gel's creep not measured, options.creep.enabled = false).
  EXPECT_LT(worst_dz_second, 0.05);
  std::printf("first lift-off: truth frame %d, tracker %d; second: truth %d, tracker %d; gel tau_c %.3f s (%.3f), "
              "c %.3f (%.3f); second press dz within %.3f mm\n",
              true_ends[0], ends[0], true_ends[1], ends[1], tracker.gelCreep().tau_c_s, gel.retardationTime(),
              tracker.gelCreep().gain, gel.creepGain(), worst_dz_second);
}

TEST(GelCreep, TheDecayAfterTheFingerLeftMeasuresTheGelBeforeTheContactEnds) {
  // creep_first_lift: a slow gel at 120 frames/s, its only press never held. After the lift the surface shrinks
  // 0.3 % a frame, and the release rule alone (gel_recovery.hpp) cannot end the contact from one frame. The
  // frames after the finger's field went, each a shrinking copy of the first, measure the gel while the contact
  // holds; the frame that measures it is analysed without the gel's delayed part and the contact ends there.
  const sim::Scenario scenario = worldScenario("creep_first_lift");
  const Recording recording = record(scenario);
  PoseTracker tracker(optionsFor(recording));
  std::vector<ReplayFrame> frames;
  for (size_t k = 0; k < recording.frames.size(); ++k)
    frames.push_back(replayFrame(recording.truth[k],
                                 tracker.update(recording.frames[k], recording.rest, recording.truth[k].t),
                                 recording.frames[k].size()));
  // The release build ends it 8 frames (0.07 s) after the truth, from a gel measured over the first frames of
  // a 0.3 %-a-frame decay: tau_c 1.95 s, c 0.31 (2.86, 0.43). That is not the 2 frames, and the
  // constants are what so short a decay gives (docs/world/README.md); it is a tenth of the wait without them.
  const ContactEvents e = contactEvents(frames);
  ASSERT_EQ(e.end_lag.size(), 1u);
  EXPECT_GE(e.end_lag[0], 0);
  EXPECT_LE(e.end_lag[0], 10);
  EXPECT_EQ(e.estimate_onset.size(), 1u);
  EXPECT_EQ(e.onsets_untouched, 0);
  const sim::ViscoelasticOptions& gel = scenario.world.viscoelastic;
  ASSERT_TRUE(tracker.gelCreep().measured());
  // Without the creep unit the contact lasts until the gel is within the contact threshold.
  ReplayOptions off;
  off.tracker.creep.enabled = false;
  const ContactEvents without = contactEvents(replay(scenario, off));
  ASSERT_EQ(without.end_lag.size(), 1u);
  EXPECT_GT(without.end_lag[0], 30);
  std::printf("lift-off %d frames late (%d without the creep unit); gel tau_c %.3f s (%.3f), c %.3f (%.3f)\n",
              e.end_lag[0], without.end_lag[0], tracker.gelCreep().tau_c_s, gel.retardationTime(),
              tracker.gelCreep().gain, gel.creepGain());
}
