// qemu_camera/camera_frames.cpp — the host side of the loopback drill.
//
//   camera_frames encode FRAMES_DIR OUT_DIR QUALITY COUNT [STRIDE]
//     COUNT frames of an image folder (onetip sim's frames/: the first, then
//     every STRIDE-th, default 1) as 8-bit
//     grey baseline JPEG files OUT_DIR/NNNNNN.jpg (cv::imencode, QUALITY 1-100):
//     what a camera's MJPEG stream carries.
//   camera_frames digest JPEG_DIR
//     the folder-source result for those files: each file read through
//     onetip's FolderSource (capture/folder_source.hpp), printed as
//     "<file> <fnv1a of its bytes> <fnv1a of the grey frame> <status>", the
//     hashes as in guest_report.hpp, so the guest's frames can be compared with them.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "capture/folder_source.hpp"
#include "guest_report.hpp"

namespace {

namespace fs = std::filesystem;
using onetip::capture::FolderSource;
using onetip::capture::FrameStatus;

int encode(const std::string& in, const std::string& out, int quality, int count, int stride) {
  FolderSource source(in);
  fs::create_directories(out);
  int written = 0;
  for (auto f = source.next(); f.status != FrameStatus::end && written < count; f = source.next()) {
    if (!f.ok() || f.index % stride != 0) continue;
    std::vector<std::uint8_t> jpeg;
    cv::imencode(".jpg", f.grey, jpeg, {cv::IMWRITE_JPEG_QUALITY, quality});
    char name[32];
    std::snprintf(name, sizeof(name), "%06d.jpg", written++);
    std::ofstream(fs::path(out) / name, std::ios::binary)
        .write(reinterpret_cast<const char*>(jpeg.data()), static_cast<std::streamsize>(jpeg.size()));
  }
  return written == count ? 0 : 1;
}

int digest(const std::string& dir) {
  FolderSource source(dir);
  const auto& files = source.files();
  for (auto f = source.next(); f.status != FrameStatus::end; f = source.next()) {
    const std::string& path = files.at(static_cast<std::size_t>(f.index));
    std::ifstream in(path, std::ios::binary);
    const std::vector<std::uint8_t> bytes(std::istreambuf_iterator<char>(in), {});
    std::printf("%s %016llx %016llx %s\n", fs::path(path).filename().c_str(),
                static_cast<unsigned long long>(onetip::qemu_camera::fnv1a(bytes.data(), bytes.size())),
                static_cast<unsigned long long>(f.ok() ? onetip::qemu_camera::hashImage(f.grey) : 0),
                onetip::capture::toString(f.status));
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  try {
    if (mode == "encode" && (argc == 6 || argc == 7))
      return encode(argv[2], argv[3], std::atoi(argv[4]), std::atoi(argv[5]),
                    argc == 7 ? std::max(1, std::atoi(argv[6])) : 1);
    if (mode == "digest" && argc == 3) return digest(argv[2]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "camera_frames: %s\n", e.what());
    return 1;
  }
  std::fprintf(stderr, "usage: camera_frames encode FRAMES_DIR OUT_DIR QUALITY COUNT [STRIDE] | digest JPEG_DIR\n");
  return 2;
}
