#include "capture/v4l2_format.hpp"

#include <linux/videodev2.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "core/error.hpp"

namespace onetip::capture {

namespace {

const std::vector<std::uint32_t>& defaultPreference() {
  static const std::vector<std::uint32_t> order{V4L2_PIX_FMT_GREY, V4L2_PIX_FMT_YUYV,
                                                V4L2_PIX_FMT_MJPEG};
  return order;
}

struct Size2 {
  int width, height;
};

// The sizes to consider for one pixel format.
std::vector<Size2> frameSizes(V4l2Io& io, int fd, std::uint32_t fourcc,
                              const V4l2FormatRequest& want) {
  std::vector<Size2> sizes;
  for (std::uint32_t i = 0;; ++i) {
    v4l2_frmsizeenum fs{};
    fs.index = i;
    fs.pixel_format = fourcc;
    if (io.ioctl(fd, VIDIOC_ENUM_FRAMESIZES, &fs) != 0) break;
    if (fs.type == V4L2_FRMSIZE_TYPE_DISCRETE) {
      sizes.push_back({static_cast<int>(fs.discrete.width), static_cast<int>(fs.discrete.height)});
      continue;
    }
    const auto& s = fs.stepwise;
    const auto on_grid = [](int v, std::uint32_t lo, std::uint32_t hi, std::uint32_t step) {
      const auto u = static_cast<std::uint32_t>(v);
      return u >= lo && u <= hi && (step == 0 || (u - lo) % step == 0);
    };
    if (on_grid(want.width, s.min_width, s.max_width, s.step_width) &&
        on_grid(want.height, s.min_height, s.max_height, s.step_height))
      sizes.push_back({want.width, want.height});
    else
      sizes.push_back({static_cast<int>(s.max_width), static_cast<int>(s.max_height)});
    break;  // stepwise/continuous: a single entry describes every size
  }
  return sizes;
}

// The shortest frame interval offered for one format and size (0/0 if none).
std::pair<std::uint32_t, std::uint32_t> shortestInterval(V4l2Io& io, int fd, std::uint32_t fourcc,
                                                         Size2 size) {
  std::pair<std::uint32_t, std::uint32_t> best{0, 0};
  double best_seconds = 1e30;
  const auto consider = [&](std::uint32_t num, std::uint32_t den) {
    if (num == 0 || den == 0) return;
    const double seconds = static_cast<double>(num) / den;
    if (seconds < best_seconds) {
      best_seconds = seconds;
      best = {num, den};
    }
  };
  for (std::uint32_t i = 0;; ++i) {
    v4l2_frmivalenum fi{};
    fi.index = i;
    fi.pixel_format = fourcc;
    fi.width = static_cast<std::uint32_t>(size.width);
    fi.height = static_cast<std::uint32_t>(size.height);
    if (io.ioctl(fd, VIDIOC_ENUM_FRAMEINTERVALS, &fi) != 0) break;
    if (fi.type == V4L2_FRMIVAL_TYPE_DISCRETE) {
      consider(fi.discrete.numerator, fi.discrete.denominator);
    } else {
      consider(fi.stepwise.min.numerator, fi.stepwise.min.denominator);
      break;
    }
  }
  return best;
}

}  // namespace

void V4l2FormatRequest::validate() const {
  if (width <= 0 || height <= 0) throw InputError("v4l2: requested frame size must be positive");
  for (auto f : preferred)
    if (!isDecodableFourcc(f))
      throw InputError("v4l2: preferred: unsupported pixel format " + fourccName(f));
}

std::string fourccName(std::uint32_t f) {
  std::string s(4, ' ');
  for (int i = 0; i < 4; ++i) {
    const char c = static_cast<char>((f >> (8 * i)) & 0xff);
    s[static_cast<size_t>(i)] = (c >= 32 && c < 127) ? c : '?';
  }
  return s;
}

bool isDecodableFourcc(std::uint32_t f) noexcept {
  return f == V4L2_PIX_FMT_MJPEG || f == V4L2_PIX_FMT_YUYV || f == V4L2_PIX_FMT_GREY;
}

std::optional<V4l2FormatOffer> chooseV4l2Format(const std::vector<V4l2FormatOffer>& offers,
                                                const V4l2FormatRequest& request) {
  const auto& order = request.preferred.empty() ? defaultPreference() : request.preferred;
  const double wanted_area = static_cast<double>(request.width) * request.height;
  // Smaller key is better.
  const auto key = [&](const V4l2FormatOffer& o) {
    const bool exact = o.width == request.width && o.height == request.height;
    const double area_gap =
        exact ? 0.0 : std::abs(std::log(static_cast<double>(o.width) * o.height / wanted_area));
    const auto rank = static_cast<long>(std::find(order.begin(), order.end(), o.fourcc) -
                                        order.begin());
    return std::make_tuple(exact ? 0 : 1, area_gap, -o.fps(), rank);
  };
  std::optional<V4l2FormatOffer> best;
  for (const auto& o : offers) {
    if (o.width <= 0 || o.height <= 0 || o.fps() <= 0.0) continue;
    if (std::find(order.begin(), order.end(), o.fourcc) == order.end()) continue;
    if (!best || key(o) < key(*best)) best = o;
  }
  return best;
}

std::vector<V4l2FormatOffer> enumerateV4l2Formats(V4l2Io& io, int fd,
                                                  const V4l2FormatRequest& request) {
  std::vector<V4l2FormatOffer> offers;
  for (std::uint32_t i = 0;; ++i) {
    v4l2_fmtdesc desc{};
    desc.index = i;
    desc.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (io.ioctl(fd, VIDIOC_ENUM_FMT, &desc) != 0) break;
    if (!isDecodableFourcc(desc.pixelformat)) continue;
    for (const Size2 size : frameSizes(io, fd, desc.pixelformat, request)) {
      auto [num, den] = shortestInterval(io, fd, desc.pixelformat, size);
      if (num == 0) {  // driver lists no intervals: assume the V4L2 default 30 Hz
        num = 1;
        den = 30;
      }
      offers.push_back({desc.pixelformat, size.width, size.height, num, den});
    }
  }
  return offers;
}

}  // namespace onetip::capture
