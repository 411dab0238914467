#include "viewer/gl_math.hpp"

#include <Eigen/Geometry>
#include <cmath>

namespace onetip::viewer {

Eigen::Matrix4f perspective(float fovy_deg, float aspect, float near_plane, float far_plane) {
  const float f = 1.0F / std::tan(0.5F * fovy_deg * static_cast<float>(M_PI) / 180.0F);
  Eigen::Matrix4f m = Eigen::Matrix4f::Zero();
  m(0, 0) = f / aspect;
  m(1, 1) = f;
  m(2, 2) = (far_plane + near_plane) / (near_plane - far_plane);
  m(2, 3) = 2.0F * far_plane * near_plane / (near_plane - far_plane);
  m(3, 2) = -1.0F;
  return m;
}

Eigen::Matrix4f lookAt(const Eigen::Vector3f& eye, const Eigen::Vector3f& target, const Eigen::Vector3f& up) {
  const Eigen::Vector3f back = (eye - target).normalized();
  const Eigen::Vector3f right = up.cross(back).normalized();
  const Eigen::Vector3f true_up = back.cross(right);
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m.block<1, 3>(0, 0) = right.transpose();
  m.block<1, 3>(1, 0) = true_up.transpose();
  m.block<1, 3>(2, 0) = back.transpose();
  m(0, 3) = -right.dot(eye);
  m(1, 3) = -true_up.dot(eye);
  m(2, 3) = -back.dot(eye);
  return m;
}

Eigen::Matrix4f orthographic(float left, float right, float bottom, float top) {
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m(0, 0) = 2.0F / (right - left);
  m(1, 1) = 2.0F / (top - bottom);
  m(0, 3) = -(right + left) / (right - left);
  m(1, 3) = -(top + bottom) / (top - bottom);
  return m;
}

Eigen::Vector4f ndcRect(const cv::Rect2d& r, cv::Size window) {
  const auto x = [&](double px) { return static_cast<float>(2.0 * px / window.width - 1.0); };
  const auto y = [&](double py) { return static_cast<float>(1.0 - 2.0 * py / window.height); };
  return {x(r.x), y(r.y + r.height), x(r.x + r.width), y(r.y)};
}

}  // namespace onetip::viewer
