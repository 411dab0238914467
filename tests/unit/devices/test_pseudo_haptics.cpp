// Pseudo-haptics (thesis Ch. 3-4): C/D ratio, K0 = F_max / D, saturation.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "devices/pseudo_haptics.hpp"

namespace onetip::devices {
namespace {

TEST(PseudoHaptics, CdRatioScalesOnlyInContact) {
  EXPECT_DOUBLE_EQ(cdScaledDisplacement(0.4, 5.0, true), 2.0);
  EXPECT_DOUBLE_EQ(cdScaledDisplacement(0.4, 5.0, false), 5.0);
}

TEST(PseudoHaptics, PlaneContactRendersStiffnessAndScalesTheAvatar) {
  PseudoHapticsOptions o;
  o.alpha = 0.5;
  o.max_device_force_n = 1.0;
  o.avatar_diameter_mm = 20.0;  // K0 = 0.05 N/mm
  const PseudoHapticPlane plane({0, 0, 0}, {0, 0, 2}, o);  // floor, normal up (normalised)
  // Sphere of radius 10 whose centre is 4 mm above the floor: 6 mm penetration.
  PseudoHapticContact c = plane.update({3, 1, 4});
  EXPECT_TRUE(c.in_contact);
  EXPECT_DOUBLE_EQ(c.real_penetration_mm, 6.0);
  EXPECT_DOUBLE_EQ(c.virtual_penetration_mm, 3.0);
  EXPECT_TRUE(c.avatar_centre.isApprox(Eigen::Vector3d(3, 1, 7)));  // drawn 3 mm in
  EXPECT_DOUBLE_EQ(c.force_n, 0.05 * 6.0);
  EXPECT_FALSE(c.saturated);
  // Out of contact: drawn where the finger is, no force.
  c = plane.update({0, 0, 10.5});
  EXPECT_FALSE(c.in_contact);
  EXPECT_DOUBLE_EQ(c.force_n, 0.0);
  EXPECT_TRUE(c.avatar_centre.isApprox(Eigen::Vector3d(0, 0, 10.5)));
  // Penetrating by the full diameter reaches F_max; beyond, it saturates.
  c = plane.update({0, 0, -10.0});
  EXPECT_NEAR(c.force_n, 1.0, 1e-12);
  EXPECT_FALSE(c.saturated);
  c = plane.update({0, 0, -12.0});
  EXPECT_DOUBLE_EQ(c.force_n, 1.0);
  EXPECT_TRUE(c.saturated);
  // Experiment 3: the force follows the virtual displacement.
  o.force_from_virtual = true;
  EXPECT_DOUBLE_EQ(PseudoHapticPlane({0, 0, 0}, {0, 0, 1}, o).update({0, 0, 4}).force_n, 0.05 * 3.0);
  o.alpha = 0.0;
  EXPECT_THROW(PseudoHapticPlane({0, 0, 0}, {0, 0, 1}, o), InputError);
}

}  // namespace
}  // namespace onetip::devices
