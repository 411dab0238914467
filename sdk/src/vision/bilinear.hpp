// vision/bilinear.hpp — bilinear sample of an 8-bit grey image at a real
// position (pixel centres at integer coordinates). The caller keeps the
// position at least one pixel inside the image; no bounds checks here.
#pragma once

#include <cmath>
#include <opencv2/core.hpp>

namespace onetip::vision {

inline float sampleBilinear(const cv::Mat& grey, float x, float y) noexcept {
  const float fx0 = std::floor(x), fy0 = std::floor(y);
  const int x0 = static_cast<int>(fx0), y0 = static_cast<int>(fy0);
  const float ax = x - fx0, ay = y - fy0;
  const unsigned char* r0 = grey.ptr<unsigned char>(y0) + x0;
  const unsigned char* r1 = grey.ptr<unsigned char>(y0 + 1) + x0;
  const float top = static_cast<float>(r0[0]) + ax * static_cast<float>(r0[1] - r0[0]);
  const float bottom = static_cast<float>(r1[0]) + ax * static_cast<float>(r1[1] - r1[0]);
  return top + ay * (bottom - top);
}

}  // namespace onetip::vision
