#include "capture/jpeg_grey_decoder.hpp"

#include <turbojpeg.h>

#include <stdexcept>
#include <string>

namespace onetip::capture {

JpegGreyDecoder::JpegGreyDecoder() : handle_(tjInitDecompress()) {
  if (handle_ == nullptr) throw std::runtime_error("TurboJPEG: cannot create a decompressor");
}

JpegGreyDecoder::~JpegGreyDecoder() { tjDestroy(static_cast<tjhandle>(handle_)); }

DecodeResult JpegGreyDecoder::decode(const std::uint8_t* data, std::size_t bytes,
                                     cv::Size expected, cv::Mat& grey) {
  DecodeResult r = decodeOnce(data, bytes, expected, grey);
  if (!r.ok) {  // a failed header read leaves the handle reporting 0x0 for the next, valid frame: start afresh
    tjDestroy(static_cast<tjhandle>(handle_));
    handle_ = tjInitDecompress();
    if (handle_ == nullptr) throw std::runtime_error("TurboJPEG: cannot create a decompressor");
  }
  return r;
}

DecodeResult JpegGreyDecoder::decodeOnce(const std::uint8_t* data, std::size_t bytes, cv::Size expected,
                                         cv::Mat& grey) {
  if (data == nullptr || bytes < 4) return {false, "empty JPEG frame"};
  const auto handle = static_cast<tjhandle>(handle_);
  int width = 0, height = 0, subsampling = 0, colorspace = 0;
  if (tjDecompressHeader3(handle, data, static_cast<unsigned long>(bytes), &width, &height,
                          &subsampling, &colorspace) != 0)
    return {false, std::string("corrupt JPEG header: ") + tjGetErrorStr2(handle)};
  if (width <= 0 || height <= 0) return {false, "the JPEG header declares no image"};
  if (expected.width > 0 && (width != expected.width || height != expected.height))
    return {false, "JPEG frame is " + std::to_string(width) + "x" + std::to_string(height) +
                       ", expected " + std::to_string(expected.width) + "x" +
                       std::to_string(expected.height)};
  cv::Mat out(height, width, CV_8UC1);
  // Warnings (e.g. "premature end of data" on a truncated frame) count as
  // failures: a partly grey frame would give wrong corners.
  if (tjDecompress2(handle, data, static_cast<unsigned long>(bytes), out.data, width,
                    static_cast<int>(out.step[0]), height, TJPF_GRAY, 0) != 0)
    return {false, std::string("corrupt JPEG data: ") + tjGetErrorStr2(handle)};
  grey = out;
  return {true, {}};
}

}  // namespace onetip::capture
