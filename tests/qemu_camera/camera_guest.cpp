// qemu_camera/camera_guest.cpp — runs inside the qemu guest (run_qemu_camera.sh)
// against real kernel V4L2 drivers through onetip's V4l2Source
// (capture/v4l2_source.hpp) alone, so the guest needs TurboJPEG and OpenCV
// core, not the image codecs' hundreds of libraries. What it prints:
// guest_report.hpp; the host checks it with check_camera.py.
//
//   camera_guest vivid DEVICE FRAMES UNLOAD_COMMAND LOAD_COMMAND   (vivid_drill.cpp)
//     640x480 YUYV, then the default request (1920x1080, GREY first) on vivid,
//     FRAMES frames counted; then vivid's "Disconnect" control pulls the plug
//     mid-stream: the source must report an error event; UNLOAD_COMMAND removes
//     the driver and the source's reconnection must fail; LOAD_COMMAND brings
//     the device back and the source must deliver frames again.
//   camera_guest loopback DEVICE JPEG_FILE...                (loopback_drill.cpp)
//     the JPEG files fed in order to v4l2loopback's output side as MJPEG and
//     read back from its capture side; then the producer goes away and comes back.
//   camera_guest feed DEVICE INTERVAL_MS FLAG_DIR JPEG_FILE...   (loopback_drill.cpp)
//     only the producer, paced, for `onetip record` and `onetip process` to read.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

namespace onetip::qemu_camera {
int runVivid(const std::string& device, int frames, const std::string& unload, const std::string& load);
int runLoopback(const std::string& device, const std::vector<std::string>& files);
int runFeed(const std::string& device, int interval_ms, const std::string& flags,
            const std::vector<std::string>& files);
}  // namespace onetip::qemu_camera

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  const std::string mode = argc > 1 ? argv[1] : "";
  try {
    if (mode == "vivid" && argc == 6)
      return onetip::qemu_camera::runVivid(argv[2], std::atoi(argv[3]), argv[4], argv[5]);
    if (mode == "loopback" && argc >= 4)
      return onetip::qemu_camera::runLoopback(argv[2], std::vector<std::string>(argv + 3, argv + argc));
    if (mode == "feed" && argc >= 6)
      return onetip::qemu_camera::runFeed(argv[2], std::atoi(argv[3]), argv[4],
                                          std::vector<std::string>(argv + 5, argv + argc));
    std::printf(
        "ONETIP ERROR usage: camera_guest vivid DEVICE FRAMES UNLOAD LOAD | loopback DEVICE JPEG... | feed DEVICE MS "
        "FLAGS JPEG...\n");
    return 2;
  } catch (const std::exception& e) {
    std::printf("ONETIP ERROR %s\n", e.what());
    return 1;
  }
}
