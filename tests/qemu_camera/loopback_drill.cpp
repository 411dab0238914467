// qemu_camera/loopback_drill.cpp — `camera_guest loopback DEVICE JPEG_FILE...`:
// a real MJPEG stream through the kernel (v4l2loopback) into V4l2Source.
//
// A producer thread opens DEVICE's output side, sets MJPEG 1920x1080 (sizeimage
// the largest file) and write()s the files in order, the next only once the
// reader has received the current one (a file not received within 1 s is
// written again: the first write lands before the reader streams). The reader
// (V4l2Source, MJPEG requested, encoded payloads kept) names each frame by its
// payload: "ONETIP MJPEG <index> <file> <bytes> <payload fnv1a> <grey fnv1a>
// <decode ms> <same> <call ms> <timestamp s>" (file -1: a payload equal to no
// file), the decode time being TurboJPEG's on that payload, timed apart, and
// <same> 1 when that decode equals the source's frame. Then the producer closes the device (the camera
// goes away mid-stream): the source must report a time-out error event; the
// producer comes back and writes the files round and round, and the source
// must deliver frames again ("ONETIP RECOVERED", guest_report.hpp).
//
// `camera_guest feed DEVICE INTERVAL_MS FLAG_DIR JPEG_FILE...` is the producer
// alone, for other programs (onetip itself) to read: it sets the format, writes
// the first file and creates FLAG_DIR/primed; once FLAG_DIR/go exists it writes
// every file, one per INTERVAL_MS, creates FLAG_DIR/fed right after the last
// one and keeps the device
// open until FLAG_DIR/stop exists (each wait at most 120 s).
#include <fcntl.h>
#include <linux/videodev2.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "capture/jpeg_grey_decoder.hpp"
#include "guest_report.hpp"

namespace onetip::qemu_camera {

namespace {

using Bytes = std::vector<std::uint8_t>;

// The output side of the loopback device.
class Producer {
 public:
  Producer(const std::string& device, const std::vector<Bytes>& files) : files_(files) {
    std::size_t largest = 0;
    for (const Bytes& f : files_) largest = std::max(largest, f.size());
    fd_ = ::open(device.c_str(), O_RDWR);
    if (fd_ < 0) throw std::runtime_error("producer: cannot open " + device);
    v4l2_format fmt{};
    fmt.type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
    fmt.fmt.pix.width = 1920, fmt.fmt.pix.height = 1080;
    fmt.fmt.pix.pixelformat = V4L2_PIX_FMT_MJPEG;
    fmt.fmt.pix.field = V4L2_FIELD_NONE;
    fmt.fmt.pix.sizeimage = static_cast<std::uint32_t>(largest);
    if (::ioctl(fd_, VIDIOC_S_FMT, &fmt) != 0) throw std::runtime_error("producer: VIDIOC_S_FMT failed");
    std::printf("ONETIP PRODUCER %s %u %u sizeimage %u\n", capture::fourccName(fmt.fmt.pix.pixelformat).c_str(),
                fmt.fmt.pix.width, fmt.fmt.pix.height, fmt.fmt.pix.sizeimage);
  }
  ~Producer() { ::close(fd_); }
  Producer(const Producer&) = delete;
  Producer& operator=(const Producer&) = delete;

  bool write(std::size_t k) {
    return ::write(fd_, files_[k].data(), files_[k].size()) == static_cast<ssize_t>(files_[k].size());
  }

 private:
  const std::vector<Bytes>& files_;
  int fd_ = -1;
};

Bytes readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  return Bytes(std::istreambuf_iterator<char>(in), {});
}

// Feeds every file in lockstep with the reader (`received`: the last file it
// got) until all are received or the reader `quit`.
void feedInOrder(Producer& producer, std::size_t n, const std::atomic<long>& received, const std::atomic<bool>& quit,
                 std::atomic<int>& rewrites) {
  for (std::size_t k = 0; k < n && !quit.load(); ++k) {
    for (int tries = 0; tries < 10 && !quit.load() && received.load() < static_cast<long>(k); ++tries) {
      if (tries > 0) ++rewrites;
      if (!producer.write(k)) std::printf("ONETIP ERROR producer: write of file %zu failed\n", k);
      const auto t0 = Clock::now();
      while (received.load() < static_cast<long>(k) && msSince(t0) < 1000)
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }
}

// Waits until `path` exists (at most `seconds`).
bool awaitFile(const std::string& path, double seconds) {
  const auto t0 = Clock::now();
  while (::access(path.c_str(), F_OK) != 0) {
    if (msSince(t0) > seconds * 1000) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return true;
}

void touch(const std::string& path) { ::close(::open(path.c_str(), O_WRONLY | O_CREAT, 0644)); }

}  // namespace

int runFeed(const std::string& device, int interval_ms, const std::string& flags,
            const std::vector<std::string>& paths) {
  std::vector<Bytes> files;
  for (const auto& p : paths) files.push_back(readFile(p));
  Producer producer(device, files);
  producer.write(0);  // readers can open the device from now on
  touch(flags + "/primed");
  if (!awaitFile(flags + "/go", 120)) {
    std::printf("ONETIP ERROR feed: no go within 120 s\n");
    return 1;
  }
  int failed = 0;
  for (std::size_t k = 0; k < files.size(); ++k) {
    if (k > 0) std::this_thread::sleep_for(std::chrono::milliseconds(interval_ms));
    failed += producer.write(k) ? 0 : 1;
  }
  std::printf("ONETIP FED %zu failed %d\n", files.size(), failed);
  touch(flags + "/fed");
  return awaitFile(flags + "/stop", 120) && failed == 0 ? 0 : 1;
}

int runLoopback(const std::string& device, const std::vector<std::string>& paths) {
  std::vector<Bytes> files;
  std::vector<std::uint64_t> hashes;
  for (const auto& p : paths) {
    files.push_back(readFile(p));
    hashes.push_back(fnv1a(files.back().data(), files.back().size()));
  }
  std::atomic<long> received{-1};
  std::atomic<int> rewrites{0};
  std::atomic<bool> quit{false};
  auto producer = std::make_unique<Producer>(device, files);
  producer->write(0);  // the capture side offers a format once a producer has written

  V4l2SourceOptions options;
  options.format.preferred = {V4L2_PIX_FMT_MJPEG};
  const auto t_open = Clock::now();
  V4l2Source source(device, options);
  std::printf("ONETIP OPENED %.1f\n", msSince(t_open));
  printFormat("FORMAT", source);
  std::printf("ONETIP KEEP-ENCODED %d\n", source.keepEncodedFrames(true) ? 1 : 0);
  std::thread feeder(feedInOrder, std::ref(*producer), files.size(), std::cref(received), std::cref(quit),
                     std::ref(rewrites));

  capture::JpegGreyDecoder decoder;
  const long last = static_cast<long>(files.size()) - 1;
  for (int calls = 0; received.load() < last && calls < 12 * static_cast<int>(files.size()); ++calls) {
    const auto t0 = Clock::now();
    const Frame f = source.next();
    const double call_ms = msSince(t0);
    if (!f.ok()) {
      printFrame(f, call_ms);
      continue;
    }
    const std::uint64_t h = fnv1a(f.encoded.data(), f.encoded.size());
    const long k = std::find(hashes.begin(), hashes.end(), h) - hashes.begin();
    cv::Mat grey;
    const auto t_dec = Clock::now();
    const bool decoded = decoder.decode(f.encoded.data(), f.encoded.size(), {1920, 1080}, grey).ok;
    const double decode_ms = msSince(t_dec);
    std::printf("ONETIP MJPEG %lld %ld %zu %016llx %016llx %.2f %d %.2f %.6f\n", static_cast<long long>(f.index),
                k < static_cast<long>(hashes.size()) ? k : -1L, f.encoded.size(), static_cast<unsigned long long>(h),
                static_cast<unsigned long long>(hashImage(f.grey)), decode_ms,
                decoded && cv::norm(grey, f.grey, cv::NORM_INF) == 0 ? 1 : 0, call_ms, f.timestamp_s);
    if (k < static_cast<long>(hashes.size())) received.store(std::max(received.load(), k));
  }
  quit.store(true);
  feeder.join();
  std::printf("ONETIP DELIVERED %ld %zu rewrites %d\n", received.load() + 1, files.size(), rewrites.load());

  // Unplug: the producer goes away mid-stream.
  producer.reset();
  const auto t_unplug = Clock::now();
  const Frame lost = source.next();
  std::printf("ONETIP UNPLUG-EVENT %.1f %s %s\n", msSince(t_unplug), capture::toString(lost.status),
              lost.message.c_str());
  const Frame again = source.next();  // the first reconnection attempt, the producer still gone
  std::printf("ONETIP WHILE-GONE %s %s\n", capture::toString(again.status), again.message.c_str());

  std::atomic<bool> stop{false};
  const auto t_back = Clock::now();
  std::thread back([&] {
    Producer p(device, files);
    for (std::size_t k = 0; !stop.load(); k = (k + 1) % files.size()) {
      p.write(k);
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  });
  const bool recovered = awaitRecovery(source, 10, t_back, t_unplug);
  if (recovered) std::printf("ONETIP RECEIVED-AFTER %d\n", receive(source, 3));
  stop.store(true);
  back.join();
  printCounters(source);
  return recovered ? 0 : 1;
}

}  // namespace onetip::qemu_camera
