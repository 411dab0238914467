// qemu_camera/vivid_drill.cpp — `camera_guest vivid DEVICE FRAMES UNLOAD LOAD`:
// V4l2Source against the kernel's vivid test driver (see camera_guest.cpp).
#include <fcntl.h>
#include <linux/videodev2.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "core/error.hpp"
#include "guest_report.hpp"

namespace onetip::qemu_camera {

namespace {

// The id of the control named `name` on the open device, or 0.
std::uint32_t findControl(int fd, const char* name) {
  v4l2_query_ext_ctrl q{};
  q.id = V4L2_CTRL_FLAG_NEXT_CTRL | V4L2_CTRL_FLAG_NEXT_COMPOUND;
  while (::ioctl(fd, VIDIOC_QUERY_EXT_CTRL, &q) == 0) {
    if (std::strcmp(q.name, name) == 0) return q.id;
    q.id |= V4L2_CTRL_FLAG_NEXT_CTRL | V4L2_CTRL_FLAG_NEXT_COMPOUND;
  }
  return 0;
}

}  // namespace

int runVivid(const std::string& device, int frames, const std::string& unload, const std::string& load) {
  try {
    V4l2Source missing("/dev/video63");
    std::printf("ONETIP MISSING-ERROR none\n");
  } catch (const InputError& e) {
    std::printf("ONETIP MISSING-ERROR %s\n", e.what());
  }
  {
    V4l2SourceOptions yuyv;
    yuyv.format.width = 640, yuyv.format.height = 480;
    yuyv.format.preferred = {V4L2_PIX_FMT_YUYV};
    V4l2Source small(device, yuyv);
    printFormat("FORMAT-SMALL", small);
    std::printf("ONETIP RECEIVED-SMALL %d\n", receive(small, 5));
  }
  const auto t_open = Clock::now();
  V4l2Source source(device);  // the defaults a user gets
  std::printf("ONETIP OPENED %.1f\n", msSince(t_open));
  printFormat("FORMAT", source);
  std::printf("ONETIP WANT %d\n", frames);
  std::printf("ONETIP RECEIVED %d\n", receive(source, frames));

  // Unplug: vivid's "Disconnect" control unregisters the device node while it streams.
  const int fd = ::open(device.c_str(), O_RDWR | O_NONBLOCK);
  const std::uint32_t id = fd >= 0 ? findControl(fd, "Disconnect") : 0;
  if (id == 0) {
    std::printf("ONETIP ERROR no Disconnect control on %s\n", device.c_str());
    return 1;
  }
  v4l2_control c{id, 0};
  const auto t_unplug = Clock::now();
  const int rc = ::ioctl(fd, VIDIOC_S_CTRL, &c);
  std::printf("ONETIP UNPLUG 0x%x %d\n", id, rc);
  ::close(fd);
  const Frame lost = source.next();
  std::printf("ONETIP UNPLUG-EVENT %.1f %s %s\n", msSince(t_unplug), capture::toString(lost.status),
              lost.message.c_str());
  // The source has let go of the device: the driver goes away altogether while the source retries.
  std::fflush(stdout);
  std::printf("ONETIP UNLOAD %d\n", std::system(unload.c_str()));
  const Frame gone = source.next();
  std::printf("ONETIP WHILE-GONE %s %s\n", capture::toString(gone.status), gone.message.c_str());
  std::fflush(stdout);
  const int load_rc = std::system(load.c_str());
  const auto t_back = Clock::now();
  std::printf("ONETIP RELOAD %d %.1f\n", load_rc, msSince(t_unplug));
  if (!awaitRecovery(source, 10, t_back, t_unplug)) return 1;
  std::printf("ONETIP RECEIVED-AFTER %d\n", receive(source, 5));
  printFormat("FORMAT-AFTER", source);
  printCounters(source);
  return 0;
}

}  // namespace onetip::qemu_camera
