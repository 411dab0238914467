// haptics/tactile_sensor_model.hpp — a simulated fingertip sensor touched by a
// flat plate: what the collection program and the objective evaluation put
// inside the display device and in the remote environment.
//
// The plate is a ContactPlane in the device frame D (platform_kinematics.hpp:
// x right, y towards the fingertip, z up into the finger; the pad's lowest
// point touches z = 0 from above). sense() fills channels() values in the
// sensor's own units; fullScale(i) is channel i's full range in those units
// (4095 counts for a 12-bit BioTac channel), the denominator of the
// "% of full range" error, or 0 when the channel has no fixed range (then
// the evaluation uses the channel's range over the dataset).
// shape() is the fingertip's outer surface near the pad, approximated by the
// ellipsoid |(q - centre) / semi_axes| = 1 in D: remote plates are placed
// against it (remote_interactions.hpp). Default: the BioTac-like fingertip,
// centre (0, 0, 7), semi-axes (7, 11, 7) mm.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "haptics/platform_kinematics.hpp"

namespace onetip::haptics {

struct FingertipShape {
  Eigen::Vector3d centre{0.0, 0.0, 7.0};
  Eigen::Vector3d semi_axes{7.0, 11.0, 7.0};
};

class TactileSensorModel {
 public:
  virtual ~TactileSensorModel() = default;
  virtual int channels() const = 0;
  virtual void sense(const ContactPlane& plate, double* out) const = 0;
  virtual double fullScale(int channel) const = 0;
  virtual FingertipShape shape() const { return {}; }

  std::vector<double> sense(const ContactPlane& plate) const {
    std::vector<double> out(static_cast<size_t>(channels()));
    sense(plate, out.data());
    return out;
  }
};

}  // namespace onetip::haptics
