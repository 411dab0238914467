// viewer/offscreen_target.hpp — a framebuffer object to draw into without a
// window (RGBA8 colour + 24-bit depth, width x height pixels), and reading a
// framebuffer back as an OpenCV image.
//
// GL's framebuffer rows run bottom-up; readFramebufferBgr() returns the image
// top-down (row 0 at the top, OpenCV order, CV_8UC3 BGR).
#pragma once

#include <opencv2/core.hpp>

#include "viewer/gl_api.hpp"

namespace onetip::viewer {

class OffscreenTarget {
 public:
  // Throws std::runtime_error when the framebuffer is incomplete.
  explicit OffscreenTarget(cv::Size size);
  ~OffscreenTarget();
  OffscreenTarget(const OffscreenTarget&) = delete;
  OffscreenTarget& operator=(const OffscreenTarget&) = delete;

  void bind() const;  // draw and read here
  cv::Size size() const noexcept { return size_; }

 private:
  cv::Size size_;
  GLuint fbo_ = 0, colour_ = 0, depth_ = 0;
};

// The bound framebuffer's pixels (0, 0)-(size) as a top-down BGR image.
cv::Mat readFramebufferBgr(cv::Size size);

}  // namespace onetip::viewer
