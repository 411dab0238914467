// pose/contact_cap.hpp — the shape of the dimple a finger presses into the
// pad, which tells how the footprint moves when the finger rolls.
//
// Over the markers of a contact region (current positions p_i in S, mm, and
// normal deformations n_i = -u_i.z) with the footprint centre c
// (contact/footprint_centre.hpp):
//  * curvature: a least-squares fit of the marker layer around c,
//      z = z0 + g . (x - c) + 1/2 (x - c)^T H (x - c)   (x = p_i.xy),
//    H the 2 x 2 curvature (1/mm) of the finger's surface where it touches
//    (the skin conforms to it); 6 unknowns, so at least 6 markers not on one
//    line (with 4 or 5, an isotropic H = k I; fewer: not valid). H is clipped
//    below at 1 / kMaxCapRadiusMm so a flat plate gives a huge but finite radius.
//  * rolling shift: a convex body whose surface near its lowest point is
//    z = 1/2 x^T H x, turned by a small rotation w (rad, S), has its lowest
//    point moved by  rho = H^-1 (w_y, -w_x)  over the pad (for a sphere of
//    radius R: R w across the tilt axis). That is how far the footprint moves
//    over the finger when the finger rolls or pitches without slipping.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace onetip {
struct MarkerField;
namespace contact {
struct ContactField;
}
}  // namespace onetip

namespace onetip::pose {

constexpr double kMaxCapRadiusMm = 1000.0;

struct ContactCap {
  bool valid = false;
  Eigen::Vector3d centre{0, 0, 0};          // footprint centre (S, mm)
  Eigen::Matrix2d curvature = Eigen::Matrix2d::Zero();  // H (1/mm)
};

ContactCap fitContactCap(const std::vector<Eigen::Vector3d>& positions, const std::vector<double>& normal_deformation,
                         double cut_mm);
// The same over a region's `members` measured in both `field` and `now`, with that region's cut.
ContactCap fitContactCap(const contact::ContactField& field, const std::vector<int>& members, const MarkerField& now);

// rho = H^-1 (w_y, -w_x) (mm, S.xy); zero for an invalid cap.
Eigen::Vector2d rollingShift(const ContactCap& cap, const Eigen::Vector3d& rotation_vector);

}  // namespace onetip::pose
