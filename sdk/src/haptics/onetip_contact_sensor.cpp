#include "haptics/onetip_contact_sensor.hpp"

#include <Eigen/Geometry>
#include <algorithm>

#include "core/error.hpp"
#include "sim/contact_model.hpp"

namespace onetip::haptics {

sim::PadOptions OnetipSensorOptions::domedPad() {
  sim::PadOptions pad;
  pad.dome_radius_mm = 21.0;
  return pad;
}

void OnetipSensorOptions::validate() const {
  pad.validate();
  if (marker_stride < 1 || marker_stride > std::max(pad.pattern.rows, pad.pattern.cols))
    throw InputError("OnetipSensorOptions.marker_stride: must be in 1..max(pattern rows, cols)");
  if (!(plate_size_mm > 0.0 && plate_size_mm <= 500.0))
    throw InputError("OnetipSensorOptions.plate_size_mm: must be in (0, 500]");
}

namespace {
// 0, stride, 2 stride, ... and always the last index.
std::vector<int> strided(int count, int stride) {
  std::vector<int> out;
  for (int i = 0; i < count; i += stride) out.push_back(i);
  if (out.back() != count - 1) out.push_back(count - 1);
  return out;
}
}  // namespace

struct OnetipContactSensor::Impl {
  sim::PadLattice lattice;
  sim::ContactModel model;
  double apex_z;
  Impl(const OnetipSensorOptions& o, const sim::IndenterGeometry& plate)
      : lattice(o.pad), model(lattice, {plate}), apex_z(o.pad.pattern.marker_depth_mm) {}
};

OnetipContactSensor::OnetipContactSensor(const OnetipSensorOptions& options) : options_(options) {
  options_.validate();
  const auto& pattern = options_.pad.pattern;
  for (int r : strided(pattern.rows, options_.marker_stride))
    for (int c : strided(pattern.cols, options_.marker_stride)) markers_.push_back(pattern.id(r, c));
  sim::IndenterGeometry plate;
  plate.shape = sim::IndenterShape::plate;
  plate.plate_width = plate.plate_length = options_.plate_size_mm;
  plate.validate();
  impl_ = std::make_unique<Impl>(options_, plate);
}

OnetipContactSensor::~OnetipContactSensor() = default;

FingertipShape OnetipContactSensor::shape() const {
  const double r = options_.pad.dome_radius_mm;
  return {Eigen::Vector3d(0.0, 0.0, r), Eigen::Vector3d::Constant(r)};
}

Eigen::Isometry3d OnetipContactSensor::platePose(const ContactPlane& plate) const {
  const Eigen::Matrix3d flip = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();
  const Eigen::Vector3d point = flip * plate.point + Eigen::Vector3d(0.0, 0.0, impl_->apex_z);
  const Eigen::Vector3d normal = flip * plate.normal.normalized();  // into the pad, downwards
  if (!(normal.z() < -1e-6))
    throw InputError("onetip sensor: the plate must face the pad (its normal must point up in D)");
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), -normal).toRotationMatrix();
  // Face point above the pad centre: normal . (q - point) = 0 with q = (0, 0, z).
  const double z = point.z() + (normal.x() * point.x() + normal.y() * point.y()) / normal.z();
  pose.translation() = Eigen::Vector3d(0.0, 0.0, z);
  return pose;
}

void OnetipContactSensor::sense(const ContactPlane& plate, double* out) const {
  const std::vector<Eigen::Isometry3d> poses = {platePose(plate)};
  impl_->model.reset(poses);
  impl_->model.advance(poses);
  for (size_t k = 0; k < markers_.size(); ++k) {
    const Eigen::Vector3d u = impl_->model.displacement(impl_->lattice.nodeOfMarker(markers_[k]));
    for (int c = 0; c < 3; ++c) out[3 * k + static_cast<size_t>(c)] = u(c);
  }
}

}  // namespace onetip::haptics
