// haptics/onetip_contact_sensor.hpp — onetip's own pad as the fingertip
// sensor of the haptic loop: the simulator's contact model (sim/contact_model.hpp)
// on a domed pad, pressed by the display platform (or a remote plate) as a
// flat sim plate indenter, reporting the markers' 3-D displacement field.
//
// Frames. The plate arrives as a ContactPlane in the device frame D
// (platform_kinematics.hpp: z up into the finger, the pad's apex touching
// z = 0 from above, the plate's normal n pointing up into the pad). The pad
// looks the other way in its own frame P (= S, pad_z up out of the skin,
// apex at z = pattern.marker_depth_mm), so D is turned 180 deg about x:
//     X_P = Rx(180) X_D + (0, 0, apex),   Rx(180) = diag(1, -1, -1)
// i.e. x_P = x_D, y_P = -y_D (the finger's tip, +y_D, is -y_P), z_P = apex - z_D.
// The plate's face in P is the plane through c_P with normal n_P = Rx(180) n
// (pointing down into the pad); the sim plate's local frame has its face at
// local z = 0 and local z away from the pad, so its pose has
//     R = the shortest rotation taking e_z to -n_P,
//     origin = the point of the face above the pad's centre (x_P = y_P = 0).
//
// Each sense() is an independent measurement: the contact model is reset
// (friction anchors cleared) with the plate at its final pose and solved once,
// as if the plate had approached along its normal without sliding, so no
// friction history leaks from one configuration to the next and the reading
// does not depend on the order of the sweep.
//
// Reading: the displacement u_k = (dx, dy, dz) in S (mm; dz < 0 pressed in)
// of the pad's markers. `marker_stride` picks every stride-th marker row and
// column (the last row and column always included), so with the default 17 x 17
// pattern a stride of 4 gives the 5 x 5 coarse grid (75 channels) and 1 the
// full field (867 channels). Channel 3 k + c is component c of the k-th picked
// marker (row-major). fullScale() is 0: displacements have no fixed count
// range; the evaluation then uses each channel's range over the dataset.
// Not thread-safe (the contact model is mutable state): one instance per thread.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <vector>

#include "haptics/tactile_sensor_model.hpp"
#include "sim/pad.hpp"

namespace onetip::haptics {

struct OnetipSensorOptions {
  sim::PadOptions pad = domedPad();
  int marker_stride = 4;      // 1: every marker; 4: the 5 x 5 grid of a 17 x 17 pattern
  double plate_size_mm = 40;  // the platform's face, square
  void validate() const;      // throws InputError naming the bad field
  // The default pad with a 21 mm dome (about the smallest its width allows).
  static sim::PadOptions domedPad();
};

class OnetipContactSensor final : public TactileSensorModel {
 public:
  explicit OnetipContactSensor(const OnetipSensorOptions& options = {});
  ~OnetipContactSensor() override;

  int channels() const override { return 3 * static_cast<int>(markers_.size()); }
  void sense(const ContactPlane& plate, double* out) const override;
  using TactileSensorModel::sense;
  double fullScale(int) const override { return 0.0; }
  FingertipShape shape() const override;

  // Marker ids picked by marker_stride, in channel order.
  const std::vector<int>& markers() const noexcept { return markers_; }
  // The pad frame pose of the sim plate for a plane given in D (see above).
  Eigen::Isometry3d platePose(const ContactPlane& plate) const;

 private:
  struct Impl;
  OnetipSensorOptions options_;
  std::vector<int> markers_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace onetip::haptics
