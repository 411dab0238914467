// viewer/gl_math.hpp — the viewer's camera matrices (column vectors, OpenGL
// clip space: x, y, z in [-1, 1] after the divide, z = -1 nearest).
//
// perspective(): symmetric frustum of vertical field of view fovy (degrees)
//   and aspect width / height between near and far (> 0, same units as the
//   scene: mm).
// lookAt(): view matrix of an eye at `eye` looking at `target`, `up` roughly
//   up (the camera's -z looks at the target, +y is up on screen).
// orthographic(): maps x in [left, right] and y in [bottom, top] to [-1, 1]
//   and keeps z; bottom > top gives top-down (image) coordinates.
// ndcRect(): a pixel rectangle of a window (top-left origin, y down) as
//   (x0, y0, x1, y1) in normalised device coordinates (y up).
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace onetip::viewer {

Eigen::Matrix4f perspective(float fovy_deg, float aspect, float near_plane, float far_plane);
Eigen::Matrix4f lookAt(const Eigen::Vector3f& eye, const Eigen::Vector3f& target, const Eigen::Vector3f& up);
Eigen::Matrix4f orthographic(float left, float right, float bottom, float top);
Eigen::Vector4f ndcRect(const cv::Rect2d& pixels, cv::Size window);

}  // namespace onetip::viewer
