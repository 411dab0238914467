#include "guest_report.hpp"

#include <cstdio>

#include "capture/v4l2_format.hpp"

namespace onetip::qemu_camera {

double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

std::uint64_t fnv1a(const std::uint8_t* data, std::size_t n) {
  std::uint64_t h = 1469598103934665603ull;
  for (std::size_t i = 0; i < n; ++i) h = (h ^ data[i]) * 1099511628211ull;
  return h;
}

std::uint64_t hashImage(const cv::Mat& grey) {
  const cv::Mat c = grey.isContinuous() ? grey : grey.clone();
  return fnv1a(c.ptr<std::uint8_t>(), c.total());
}

void printFormat(const char* tag, const V4l2Source& source) {
  const auto& f = source.format();
  std::printf("ONETIP %s %s %d %d %.3f\n", tag, capture::fourccName(f.fourcc).c_str(), f.width, f.height, f.fps());
}

void printFrame(const Frame& f, double call_ms) {
  double mean = 0, stddev = 0;
  if (f.ok()) {
    cv::Scalar m, s;
    cv::meanStdDev(f.grey, m, s);
    mean = m[0], stddev = s[0];
  }
  std::printf("ONETIP FRAME %lld %s %.6f %d %d %.2f %.2f %.2f %s\n", static_cast<long long>(f.index),
              capture::toString(f.status), f.timestamp_s, f.grey.cols, f.grey.rows, mean, stddev, call_ms,
              f.message.c_str());
}

void printCounters(const V4l2Source& source) {
  const auto& n = source.counters();
  std::printf("ONETIP COUNTERS %lld %lld %lld\n", static_cast<long long>(n.delivered),
              static_cast<long long>(n.skipped), static_cast<long long>(n.errors));
}

int receive(V4l2Source& source, int count) {
  int ok = 0;
  for (int calls = 0; ok < count && calls < 3 * count + 10; ++calls) {
    const auto t0 = Clock::now();
    const Frame f = source.next();
    printFrame(f, msSince(t0));
    if (f.status == FrameStatus::end) break;
    ok += f.ok() ? 1 : 0;
  }
  return ok;
}

bool awaitRecovery(V4l2Source& source, int max_calls, Clock::time_point back, Clock::time_point unplug) {
  for (int calls = 0; calls < max_calls; ++calls) {
    const auto t0 = Clock::now();
    const Frame f = source.next();
    printFrame(f, msSince(t0));
    if (f.status == FrameStatus::error) std::printf("ONETIP EVENT error %s\n", f.message.c_str());
    if (f.status == FrameStatus::end) return false;
    if (f.ok()) {
      std::printf("ONETIP RECOVERED %.1f %.1f\n", msSince(back), msSince(unplug));
      return true;
    }
  }
  return false;
}

}  // namespace onetip::qemu_camera
