// capture/v4l2_format.hpp — what a V4L2 camera offers and which mode to use.
//
// An offer is one (pixel format, frame size, frame interval) the driver lists
// through VIDIOC_ENUM_FMT / ENUM_FRAMESIZES / ENUM_FRAMEINTERVALS. Only the
// formats this SDK decodes take part: MJPEG, YUYV and GREY.
// chooseV4l2Format ranks offers by, in order:
//   1. the requested frame size exactly (1920x1080 by default); failing that,
//      the size closest in area (|log(area / requested area)|);
//   2. the highest frame rate;
//   3. the earlier format in `preferred` (default GREY, YUYV, MJPEG: at an
//      equal size and rate the uncompressed formats cost less to decode and
//      carry no compression artefacts that would bias sub-pixel corners).
// Stepwise and continuous sizes/intervals are represented by the requested
// size when it lies on the step grid (else the largest size) and by their
// shortest interval.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "capture/v4l2_io.hpp"

namespace onetip::capture {

struct V4l2FormatOffer {
  std::uint32_t fourcc = 0;
  int width = 0, height = 0;
  std::uint32_t interval_num = 1, interval_den = 30;  // seconds per frame
  double fps() const noexcept {
    return interval_num == 0 ? 0.0 : static_cast<double>(interval_den) / interval_num;
  }
};

struct V4l2FormatRequest {
  int width = 1920, height = 1080;
  std::vector<std::uint32_t> preferred;  // empty: GREY, YUYV, MJPEG
  void validate() const;                 // throws InputError naming the bad field
};

// "MJPG", "YUYV", "GREY", ... from a V4L2 fourcc.
std::string fourccName(std::uint32_t fourcc);
bool isDecodableFourcc(std::uint32_t fourcc) noexcept;

std::optional<V4l2FormatOffer> chooseV4l2Format(const std::vector<V4l2FormatOffer>& offers,
                                                const V4l2FormatRequest& request);

// Every decodable offer of the open device `fd` (empty if none; never throws).
std::vector<V4l2FormatOffer> enumerateV4l2Formats(V4l2Io& io, int fd,
                                                  const V4l2FormatRequest& request);

}  // namespace onetip::capture
