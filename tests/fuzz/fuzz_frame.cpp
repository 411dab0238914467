// Fuzzes the frame decode paths: image files (header check, then cv::imdecode
// to grey; capture/image_file.hpp) and MJPEG frames through TurboJPEG at a
// negotiated size (capture/jpeg_grey_decoder.hpp). Any outcome but a grey
// image of the declared size or a reason is a failure.
#include <cstdint>

#include "capture/image_file.hpp"
#include "capture/jpeg_grey_decoder.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace onetip::capture;
  ImageLimits limits;
  limits.max_pixels = 4'000'000;  // keeps each run cheap; the check is the same at any bound
  const GreyImage image = decodeGreyImage(data, size, limits);
  if (image.problem ? !image.grey.empty() : (image.grey.type() != CV_8UC1 || image.grey.empty())) __builtin_trap();
  static JpegGreyDecoder jpeg;
  cv::Mat grey;
  const DecodeResult r = jpeg.decode(data, size, {640, 480}, grey);
  if (r.ok && (grey.cols != 640 || grey.rows != 480)) __builtin_trap();
  return 0;
}
