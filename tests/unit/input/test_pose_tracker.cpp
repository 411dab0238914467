#include <gtest/gtest.h>

#include <algorithm>

#include "core/error.hpp"
#include "replay_metrics.hpp"
#include "sim/simulator.hpp"

using namespace onetip;
using namespace onetip::poseval;
using input::EventType;

namespace {
int count(const std::vector<ReplayFrame>& frames, EventType type) {
  int n = 0;
  for (const auto& f : frames) n += static_cast<int>(std::count(f.events.begin(), f.events.end(), type));
  return n;
}
}  // namespace

TEST(PoseTracker, PressEventsFollowTheTrueDepth) {
  const auto frames = replay(sampleScenario("press"));
  EXPECT_EQ(count(frames, EventType::contact_begin), 1);
  EXPECT_EQ(count(frames, EventType::contact_end), 1);
  EXPECT_EQ(count(frames, EventType::press), 1);
  EXPECT_EQ(count(frames, EventType::release), 1);
  // The press fires within a frame of the true depth crossing 1.5 mm.
  for (size_t k = 1; k < frames.size(); ++k) {
    if (std::count(frames[k].events.begin(), frames[k].events.end(), EventType::press) == 0) continue;
    EXPECT_NEAR(frames[k].gt.dz, 1.5, 0.15);
  }
  int inputs = 0, in_contact = 0;
  for (const auto& f : frames) {
    inputs += static_cast<int>(std::count(f.events.begin(), f.events.end(), EventType::input));
    in_contact += f.contact ? 1 : 0;
  }
  EXPECT_EQ(inputs, in_contact);  // one input event every frame in contact
}

TEST(PoseTracker, StateChangesAreReported) {
  const auto frames = replay(sampleScenario("slide_x"));
  EXPECT_GE(count(frames, EventType::state_changed), 3);  // none -> stick -> ... -> slip -> none
  bool saw_partial = false, saw_slip = false;
  for (const auto& f : frames) {
    saw_partial = saw_partial || f.state == ContactState::partial_slip;
    saw_slip = saw_slip || f.state == ContactState::slip;
  }
  EXPECT_TRUE(saw_partial);
  EXPECT_TRUE(saw_slip);
}

TEST(PoseTracker, LostMarkersHoldTheOutputWithAnErrorEvent) {
  sim::Simulator s(sampleScenario("press"));
  input::PoseTracker tracker;
  input::TrackerResult last;
  while (!s.done()) {
    const auto& f = s.next();
    last = tracker.update(f.markers, s.restMarkers(), f.t);
    if (f.input.dz > 1.0) break;
  }
  ASSERT_TRUE(last.contact);
  MarkerField blind = s.current().markers;
  std::fill(blind.valid.begin(), blind.valid.end(), 0);
  const auto held = tracker.update(blind, s.restMarkers(), s.current().t + 0.033);
  EXPECT_TRUE(held.held);
  EXPECT_TRUE(held.contact);
  EXPECT_DOUBLE_EQ(held.raw.dz, last.raw.dz);
  ASSERT_EQ(held.events.size(), 1u);
  EXPECT_EQ(held.events[0].type, EventType::error);
  EXPECT_NE(held.events[0].message.find("too few valid markers"), std::string::npos);
}

TEST(PoseTracker, MismatchedGridsAndBadOptionsThrow) {
  input::PoseTracker tracker;
  EXPECT_THROW(tracker.update(MarkerField(17, 17), MarkerField(9, 9), 0), InputError);
  input::PoseTrackerOptions o;
  o.clamp_factor = 0.5;
  EXPECT_THROW(input::PoseTracker{o}, InputError);
}
