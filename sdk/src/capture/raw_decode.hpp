// capture/raw_decode.hpp — uncompressed camera payloads to 8-bit grey.
//
// YUYV (YUY2, 4:2:2): each pair of pixels is 4 bytes Y0 U Y1 V; grey is the
// luma Y, i.e. every even byte. GREY (Y8): one byte per pixel. bytes_per_line
// is the driver's line stride (>= 2*width for YUYV, >= width for GREY); a
// payload shorter than bytes_per_line * (height - 1) + one line of pixels is
// truncated and rejected. Pure functions over bytes, so recorded frames test
// them without a device.
#pragma once

#include <cstddef>
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

namespace onetip::capture {

struct DecodeResult {
  bool ok = false;
  std::string message;  // why not, when !ok
};

// Writes a width x height CV_8UC1 image into `grey` (reallocated if needed).
DecodeResult yuyvToGrey(const std::uint8_t* data, std::size_t bytes, int width, int height,
                        std::size_t bytes_per_line, cv::Mat& grey);
DecodeResult greyToGrey(const std::uint8_t* data, std::size_t bytes, int width, int height,
                        std::size_t bytes_per_line, cv::Mat& grey);

}  // namespace onetip::capture
