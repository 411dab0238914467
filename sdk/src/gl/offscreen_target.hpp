// gl/offscreen_target.hpp — a framebuffer object to draw into without a
// window: one colour renderbuffer of a given internal format (GL_RGBA8 for the
// viewer's panels, GL_R32F for the simulator's float grey levels) + 24-bit
// depth, width x height pixels; and reading a framebuffer back as an OpenCV
// image.
//
// GL's framebuffer rows run bottom-up; readFramebufferBgr() returns the image
// top-down (row 0 at the top, OpenCV order, CV_8UC3 BGR).
//
// Threading: a current 3.3 core context (gl/headless_context.hpp) is needed
// for every call, construction and destruction included; use the target only
// in the context that made it.
#pragma once

#include <opencv2/core.hpp>

#include "gl/gl_api.hpp"

namespace onetip::gl {

class OffscreenTarget {
 public:
  // `colour_format`: the colour renderbuffer's sized internal format, e.g.
  // GL_RGBA8 or GL_R32F. Throws std::runtime_error when the framebuffer is
  // incomplete (e.g. the format cannot be rendered to).
  OffscreenTarget(cv::Size size, GLenum colour_format);
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

}  // namespace onetip::gl
