// viewer/gl_texture.hpp — an owning wrapper of the OpenGL 2-D texture the
// viewer draws images from (the camera frame, the text overlay): linear
// filtering, clamped edges; CV_8UC1 images become one-channel (R8) textures,
// CV_8UC4 (BGRA, OpenCV order) RGBA. Sizes and regions are in pixels.
//
// Threading: a current 3.3 core context (gl/headless_context.hpp or the GLFW
// window's) is needed for every call, construction and destruction included.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "gl/gl_api.hpp"

namespace onetip::viewer {

class GlTexture {
 public:
  GlTexture();
  ~GlTexture();
  GlTexture(const GlTexture&) = delete;
  GlTexture& operator=(const GlTexture&) = delete;

  // Throws std::invalid_argument for an empty image or a type other than
  // CV_8UC1 / CV_8UC4.
  void upload(const cv::Mat& image);
  // Updates only `regions` (pixels, inside the image) from `image`, or all of
  // it when its size or type differs from the texture's; texels outside the
  // regions keep what they held.
  void uploadRegions(const cv::Mat& image, const std::vector<cv::Rect>& regions);
  void bind(int unit) const;
  bool empty() const noexcept { return size_.area() == 0; }

 private:
  GLuint texture_ = 0;
  cv::Size size_;
  int type_ = -1;
};

}  // namespace onetip::viewer
