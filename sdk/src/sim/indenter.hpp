// sim/indenter.hpp — rigid bodies that press the pad: ellipsoid finger,
// sphere, flat plate.
//
// Each shape is described in its own local frame, whose origin is the shape's
// lowest point at identity pose (the "tip") and whose z points up, away from
// the pad:
//   ellipsoid: centre (0, 0, c), semi-axes (a, b, c) along local x, y, z
//              (default finger 7 x 9 x 6 mm, long axis along y);
//   sphere:    an ellipsoid with a = b = c = radius;
//   plate:     lower face z = 0, |x| <= width/2, |y| <= length/2 (thin, rigid).
// A pose maps local to the sensor frame S: X_S = pose * X_local (mm).
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>

namespace onetip::sim {

enum class IndenterShape { ellipsoid, sphere, plate };

struct IndenterGeometry {
  IndenterShape shape = IndenterShape::ellipsoid;
  Eigen::Vector3d semi_axes{7.0, 9.0, 6.0};  // ellipsoid / sphere (radius in all three)
  double plate_width = 30.0, plate_length = 30.0;  // plate, mm

  void validate() const;  // throws InputError naming the bad field
  static IndenterShape shapeFromName(const std::string& name);  // throws InputError
};

// Height (S.z, mm) of the posed body's lower surface above the point (x, y),
// or nullopt when the vertical line through (x, y) misses the body.
std::optional<double> lowerSurfaceZ(const IndenterGeometry& g, const Eigen::Isometry3d& pose,
                                    double x, double y);

// The lowest S.z of the posed body (its support in direction -z).
double lowestZ(const IndenterGeometry& g, const Eigen::Isometry3d& pose);

// The (x, y) half-extent around the pose's origin that bounds the body's
// footprint: used to skip lattice nodes the body cannot touch.
double footprintRadius(const IndenterGeometry& g);

}  // namespace onetip::sim
