#include "capture/raw_decode.hpp"

#include <cstring>

namespace onetip::capture {

namespace {
DecodeResult checkPayload(std::size_t bytes, int width, int height, std::size_t bytes_per_line,
                          std::size_t bytes_per_pixel) {
  if (width <= 0 || height <= 0) return {false, "frame size is not positive"};
  const std::size_t line = static_cast<std::size_t>(width) * bytes_per_pixel;
  if (bytes_per_line < line) return {false, "line stride shorter than a line of pixels"};
  const std::size_t needed = bytes_per_line * static_cast<std::size_t>(height - 1) + line;
  if (bytes < needed)
    return {false, "truncated frame: " + std::to_string(bytes) + " bytes, expected " +
                       std::to_string(needed)};
  return {true, {}};
}
}  // namespace

DecodeResult yuyvToGrey(const std::uint8_t* data, std::size_t bytes, int width, int height,
                        std::size_t bytes_per_line, cv::Mat& grey) {
  DecodeResult r = checkPayload(bytes, width, height, bytes_per_line, 2);
  if (!r.ok) return r;
  grey.create(height, width, CV_8UC1);
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* src = data + bytes_per_line * static_cast<std::size_t>(y);
    std::uint8_t* dst = grey.ptr<std::uint8_t>(y);
    for (int x = 0; x < width; ++x) dst[x] = src[2 * x];
  }
  return r;
}

DecodeResult greyToGrey(const std::uint8_t* data, std::size_t bytes, int width, int height,
                        std::size_t bytes_per_line, cv::Mat& grey) {
  DecodeResult r = checkPayload(bytes, width, height, bytes_per_line, 1);
  if (!r.ok) return r;
  grey.create(height, width, CV_8UC1);
  for (int y = 0; y < height; ++y)
    std::memcpy(grey.ptr<std::uint8_t>(y), data + bytes_per_line * static_cast<std::size_t>(y),
                static_cast<std::size_t>(width));
  return r;
}

}  // namespace onetip::capture
