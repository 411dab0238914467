// capture/jpeg_grey_decoder.hpp — MJPEG frames straight to 8-bit grey.
//
// libjpeg-turbo's TurboJPEG API (tjDecompress2 with TJPF_GRAY) decodes only
// the luma plane, skipping chroma upsampling and colour conversion; it
// measured faster than cv::imdecode(IMREAD_GRAYSCALE) on 1920x1080 frames
// (tests/bench/vision/bench_decode.cpp). Motion-JPEG frames from webcams that
// omit the Huffman tables decode with the standard tables. Corrupt or
// truncated data, and a frame whose header size differs from the expected
// one, give !ok with the decoder's message; no exception, no partial image.
// After a failure the TurboJPEG handle is replaced: a failed header read
// otherwise made it report 0x0 for the next, valid frame.
// One decoder per thread (it owns a TurboJPEG handle).
#pragma once

#include <cstddef>
#include <cstdint>
#include <opencv2/core.hpp>

#include "capture/raw_decode.hpp"

namespace onetip::capture {

class JpegGreyDecoder {
 public:
  JpegGreyDecoder();  // throws std::runtime_error if TurboJPEG cannot start
  ~JpegGreyDecoder();
  JpegGreyDecoder(const JpegGreyDecoder&) = delete;
  JpegGreyDecoder& operator=(const JpegGreyDecoder&) = delete;

  // expected: the negotiated size, or {0, 0} to accept the header's size.
  DecodeResult decode(const std::uint8_t* data, std::size_t bytes, cv::Size expected,
                      cv::Mat& grey);

 private:
  DecodeResult decodeOnce(const std::uint8_t* data, std::size_t bytes, cv::Size expected, cv::Mat& grey);
  void* handle_ = nullptr;  // tjhandle
};

}  // namespace onetip::capture
