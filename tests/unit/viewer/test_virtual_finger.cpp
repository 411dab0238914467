// The virtual finger's controls, and Simulator::nextPosed against the
// simulator's own keyframe playback.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "sim/simulator.hpp"
#include "viewer/virtual_finger.hpp"

namespace onetip::viewer {
namespace {

TEST(VirtualFinger, StepsAreLimitedAndThePoseStaysInRange) {
  VirtualFinger f;
  const VirtualFingerOptions& o = f.options();
  EXPECT_DOUBLE_EQ(f.pose().depth, o.rest_depth_mm);
  FingerControls c;
  c.press = 10.0;
  c.twist = -10.0;
  c.slide_x = 0.1;
  f.apply(c);
  EXPECT_DOUBLE_EQ(f.pose().depth, o.rest_depth_mm + o.max_step_mm);
  EXPECT_DOUBLE_EQ(f.pose().yaw, -o.max_step_deg);
  EXPECT_DOUBLE_EQ(f.pose().x, 0.1);
  for (int i = 0; i < 200; ++i) f.apply(c);
  EXPECT_DOUBLE_EQ(f.pose().depth, o.max_depth_mm);
  EXPECT_DOUBLE_EQ(f.pose().yaw, -o.max_yaw_deg);
  EXPECT_DOUBLE_EQ(f.pose().x, o.max_offset_mm);
  FingerControls lift;
  lift.lift = true;
  f.apply(lift);
  EXPECT_DOUBLE_EQ(f.pose().depth, o.rest_depth_mm);
  EXPECT_DOUBLE_EQ(f.pose().x, 0.0);
  EXPECT_DOUBLE_EQ(f.pose().yaw, 0.0);
  VirtualFingerOptions bad;
  bad.max_step_mm = 0;
  EXPECT_THROW(VirtualFinger{bad}, InputError);
}

TEST(SimulatorNextPosed, ReproducesKeyframePlayback) {
  sim::Scenario sc = virtualFingerScenario();
  sc.fps = 30;
  sc.indenters[0].keyframes = {{0.0, 0, 0, -0.3, 0, 0, 0}, {0.3, 0, 0, 1.2, 0, 0, 0}, {0.5, 0.6, 0.2, 1.2, 5, 0, 0}};
  sim::Simulator played(sc), posed(sc);
  for (int k = 0; k < played.frameCount(); ++k) {
    const sim::GroundTruthFrame& a = played.next();
    const sim::GroundTruthFrame& b = posed.nextPosed({sc.indenters[0].at(k / sc.fps)});
    ASSERT_EQ(a.index, b.index);
    EXPECT_NEAR(a.t, b.t, 1e-9);
    for (int id = 0; id < a.markers.size(); ++id)
      ASSERT_NEAR((a.markers.position[static_cast<size_t>(id)] - b.markers.position[static_cast<size_t>(id)]).norm(),
                  0.0, 1e-9)
          << "frame " << k << " marker " << id;
    EXPECT_EQ(a.in_contact, b.in_contact);
  }
  EXPECT_TRUE(posed.current().in_contact);
  EXPECT_THROW(posed.nextPosed({}), InputError);
}

}  // namespace
}  // namespace onetip::viewer
