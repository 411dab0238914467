#include "dds/ros_messages.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include "core/rotation.hpp"
#include "pipeline/frame_processor.hpp"

namespace onetip::dds {

RosTime rosTime(double s) {
  const double whole = std::floor(s);
  auto ns = static_cast<std::int64_t>(std::llround((s - whole) * 1e9));
  auto sec = static_cast<std::int64_t>(whole);
  if (ns >= 1000000000) {
    ns -= 1000000000;
    ++sec;
  }
  return {static_cast<std::int32_t>(sec), static_cast<std::uint32_t>(ns)};
}

double seconds(const RosTime& t) { return static_cast<double>(t.sec) + 1e-9 * static_cast<double>(t.nanosec); }

std::array<float, 6> joyAxes(const Input6& v, const std::array<double, 6>& working_range) {
  const auto a = v.asArray();
  std::array<float, 6> out{};
  for (size_t i = 0; i < 6; ++i) out[i] = static_cast<float>(std::clamp(a[i] / working_range[i], -1.0, 1.0));
  return out;
}

std::array<double, 4> quaternionXyzw(const Input6& v) {
  Eigen::Quaterniond q(rotationFromYawPitchRoll(v.yaw * kRadPerDeg, v.pitch * kRadPerDeg, v.roll * kRadPerDeg));
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  return {q.x(), q.y(), q.z(), q.w()};
}

std::array<double, 3> positionMetres(const Input6& v) { return {v.dx * 1e-3, v.dy * 1e-3, -v.dz * 1e-3}; }

const std::array<CloudField, 6>& markerCloudFields() {
  static const std::array<CloudField, 6> fields{{{"x", 0, kPointFieldFloat64},
                                                 {"y", 8, kPointFieldFloat64},
                                                 {"z", 16, kPointFieldFloat64},
                                                 {"displacement", 24, kPointFieldFloat64},
                                                 {"id", 32, kPointFieldUint32},
                                                 {"label", 36, kPointFieldUint8}}};
  return fields;
}

MarkerCloud markerCloud(const pipeline::FrameResult& r) {
  static_assert(std::endian::native == std::endian::little, "PointCloud2 data is written little endian");
  MarkerCloud cloud;
  const MarkerField& m = r.markers;
  const contact::ContactField& field = r.pose.field;
  const auto& labels = r.pose.step.labels;
  cloud.data.reserve(static_cast<size_t>(m.validCount()) * kMarkerPointStep);
  for (int id = 0; id < m.size(); ++id) {
    const auto i = static_cast<size_t>(id);
    if (!m.valid[i]) continue;
    std::uint8_t point[kMarkerPointStep] = {};
    const double xyz_disp[4] = {
        m.position[i].x() * 1e-3, m.position[i].y() * 1e-3, m.position[i].z() * 1e-3,
        i < field.valid.size() && field.valid[i] ? field.displacement[i].norm() * 1e-3 : 0.0};
    std::memcpy(point, xyz_disp, sizeof xyz_disp);
    const auto id32 = static_cast<std::uint32_t>(id);
    std::memcpy(point + 32, &id32, sizeof id32);
    point[36] = i < labels.size() ? static_cast<std::uint8_t>(labels[i]) : 0;
    cloud.data.insert(cloud.data.end(), point, point + kMarkerPointStep);
    ++cloud.width;
  }
  return cloud;
}

}  // namespace onetip::dds
