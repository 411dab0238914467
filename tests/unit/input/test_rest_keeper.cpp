// The rest kept true while nothing touches (input/rest_keeper.hpp): a shifted
// camera is followed and reported, a press is not mistaken for one, slow
// drift is followed without a false contact, hidden markers are named.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

#include "input/pose_tracker.hpp"
#include "input/rest_keeper.hpp"
#include "sim_replay.hpp"

using namespace onetip;
using namespace onetip::input;

namespace {

constexpr double kNoise = 0.0006;  // mm per axis, the front end's at default image quality

MarkerField grid(int n, double pitch = 1.2) {
  MarkerField f(n, n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) f.set(r * n + c, {(c - (n - 1) / 2.0) * pitch, (r - (n - 1) / 2.0) * pitch, 0});
  return f;
}

MarkerField noisy(const MarkerField& f, std::mt19937& rng, const Eigen::Vector3d& shift = Eigen::Vector3d::Zero()) {
  std::normal_distribution<double> n(0, kNoise);
  MarkerField out = f;
  for (auto& p : out.position) p += shift + Eigen::Vector3d(n(rng), n(rng), n(rng));
  return out;
}

double largestOffset(const MarkerField& a, const MarkerField& b) {
  double m = 0;
  for (size_t i = 0; i < a.position.size(); ++i) m = std::max(m, (a.position[i] - b.position[i]).norm());
  return m;
}

}  // namespace

TEST(RestKeeper, AnInPlaneShiftOfTheWholeFieldIsFollowedAndReported) {
  std::mt19937 rng(1);
  const MarkerField rest = grid(17);
  RestKeeper keeper;
  keeper.update(noisy(rest, rng), rest, false, kNoise, 0.1, 0.0);
  const Eigen::Vector3d shift(0.08, -0.05, 0);
  const RestUpdate u = keeper.update(noisy(rest, rng, shift), rest, false, kNoise, 0.1, 1.0 / 30);
  EXPECT_TRUE(u.moved);
  EXPECT_NEAR(u.moved_mm, shift.norm(), 0.003);
  MarkerField shifted = rest;
  for (auto& p : shifted.position) p += shift;
  EXPECT_LT(largestOffset(keeper.rest(), shifted), 0.002);
}

TEST(RestKeeper, APressIsNotAMoveOfTheSensor) {
  std::mt19937 rng(2);
  const MarkerField rest = grid(17);
  RestKeeper keeper;
  keeper.update(noisy(rest, rng), rest, false, kNoise, 0.1, 0.0);
  // A flat plate over the whole pattern: every marker 0.05 mm into the pad, rigidly.
  RestUpdate u = keeper.update(noisy(rest, rng, {0, 0, -0.05}), rest, false, kNoise, 0.1, 1.0 / 30);
  EXPECT_FALSE(u.moved);
  EXPECT_LT(largestOffset(keeper.rest(), rest), 0.001);
  // A fingertip: a dimple of 0.2 mm at the centre, the rest of the pad still.
  MarkerField dimple = noisy(rest, rng);
  for (int id : {143, 144, 145, 127, 161}) dimple.position[static_cast<size_t>(id)].z() -= 0.2;
  u = keeper.update(dimple, rest, false, kNoise, 0.1, 2.0 / 30);
  EXPECT_FALSE(u.moved);
  EXPECT_LT(largestOffset(keeper.rest(), rest), 0.001);
}

TEST(RestKeeper, MarkersMissingForTwoSecondsAreNamedOnce) {
  const MarkerField rest = grid(9);
  RestKeeper keeper;
  std::vector<int> reported;
  for (int k = 0; k <= 90; ++k) {
    MarkerField now = rest;
    now.valid[10] = now.valid[33] = 0;
    const RestUpdate u = keeper.update(now, rest, false, kNoise, 0.1, k / 30.0);
    reported.insert(reported.end(), u.hidden.begin(), u.hidden.end());
    if (k < 59) {
      EXPECT_TRUE(u.hidden.empty()) << "frame " << k;
    }
  }
  EXPECT_EQ(reported, (std::vector<int>{10, 33}));
  EXPECT_NE(describeHidden(reported).find("10, 33"), std::string::npos);
}

TEST(RestKeeper, MarkersMissingFromTheRestStateAreNamedWithTheFirstFrame) {
  MarkerField rest = grid(9);
  rest.valid[5] = rest.valid[71] = 0;  // damaged before the sensor started
  RestKeeper keeper;
  std::vector<int> reported;
  for (int k = 0; k <= 90; ++k) {
    const RestUpdate u = keeper.update(rest, rest, false, kNoise, 0.1, k / 30.0);
    if (k > 0) {
      EXPECT_TRUE(u.hidden.empty()) << "frame " << k;
    }
    reported.insert(reported.end(), u.hidden.begin(), u.hidden.end());
  }
  EXPECT_EQ(reported, (std::vector<int>{5, 71}));
}

TEST(RestKeeper, TenMinutesOfSlowDriftAtRestStartNoContact) {
  // The rest state swells by 0.1 mm over ten minutes (a thermal drift), the camera at 30 fps.
  std::mt19937 rng(3);
  const MarkerField rest = grid(17);
  PoseTracker tracker;
  int onsets = 0;
  const int frames = 30 * 600;
  for (int k = 0; k < frames; ++k) {
    const double s = 0.1 * k / frames;
    MarkerField now = noisy(rest, rng);
    for (auto& p : now.position) p += s * Eigen::Vector3d(p.x() / 10, p.y() / 10, 1);
    const TrackerResult r = tracker.update(now, rest, k / 30.0);
    for (const InputEvent& e : r.events) onsets += e.type == EventType::contact_begin ? 1 : 0;
  }
  EXPECT_EQ(onsets, 0);
}

TEST(RestKeeper, AfterACameraShiftThePressReadsAsBefore) {
  using namespace onetip::poseval;
  const Recording clean = record(sampleScenario("press"));
  Recording shifted = clean;
  // The camera shifts by 0.1 mm in x at the third frame, long before the touch.
  for (size_t k = 3; k < shifted.frames.size(); ++k)
    for (auto& p : shifted.frames[k].position) p.x() += 0.1;
  PoseTracker tracker;
  int moved_events = 0, onset_frame = -1;
  double deepest = 0, deepest_clean = 0;
  for (size_t k = 0; k < shifted.frames.size(); ++k) {
    const TrackerResult r = tracker.update(shifted.frames[k], shifted.rest, shifted.truth[k].t);
    for (const InputEvent& e : r.events) {
      if (e.type == EventType::error && e.message.find("camera moved") != std::string::npos) ++moved_events;
      if (e.type == EventType::contact_begin && onset_frame < 0) onset_frame = static_cast<int>(k);
    }
    deepest = std::max(deepest, r.raw.dz);
  }
  for (const ReplayFrame& f : track(clean)) deepest_clean = std::max(deepest_clean, f.raw.dz);
  EXPECT_EQ(moved_events, 1);
  int true_onset = -1;
  for (size_t k = 0; k < clean.truth.size() && true_onset < 0; ++k)
    if (clean.truth[k].in_contact) true_onset = static_cast<int>(k);
  EXPECT_NEAR(onset_frame, true_onset, 1);
  EXPECT_NEAR(deepest, deepest_clean, 0.1 * deepest_clean);
}
