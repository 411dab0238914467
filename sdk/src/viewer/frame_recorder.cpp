#include "viewer/frame_recorder.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace onetip::viewer {

namespace fs = std::filesystem;

void writePngAtomically(const std::string& path, const cv::Mat& bgr) {
  std::vector<unsigned char> png;
  if (bgr.empty() || !cv::imencode(".png", bgr, png, {cv::IMWRITE_PNG_COMPRESSION, 1}))
    throw InputError(path + ": cannot encode the image as PNG");
  AtomicFile out(path);
  out.stream().write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  out.commit();
}

FrameRecorder::FrameRecorder(std::string target, double fps) : target_(std::move(target)), fps_(fps) {
  if (!(fps > 0 && fps <= 1000)) throw InputError("--record: frame rate must be in (0, 1000]");
  const fs::path path(target_);
  const std::string ext = path.extension().string();
  if (ext == ".mp4" || ext == ".avi") {
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    if (!fs::is_directory(folder)) throw InputError("--record " + target_ + ": folder does not exist");
    video_path_ = (folder / (path.stem().string() + ".part" + std::to_string(::getpid()) + ext)).string();
    return;
  }
  std::error_code ec;
  fs::create_directories(path, ec);
  if (!fs::is_directory(path)) throw InputError("--record " + target_ + ": cannot create the folder");
}

FrameRecorder::~FrameRecorder() {
  if (!video_path_.empty() && !finished_) {
    video_.reset();
    std::error_code ec;
    fs::remove(video_path_, ec);
  }
}

void FrameRecorder::write(const cv::Mat& bgr) {
  if (bgr.empty() || bgr.type() != CV_8UC3) throw InputError("--record: expected 8-bit BGR frames");
  if (written_ == 0) size_ = bgr.size();
  if (bgr.size() != size_) throw InputError("--record: the frame size changed while recording");
  if (isVideo()) {
    if (!video_) {
      const bool mp4 = fs::path(target_).extension() == ".mp4";
      const int fourcc = mp4 ? cv::VideoWriter::fourcc('m', 'p', '4', 'v') : cv::VideoWriter::fourcc('M', 'J', 'P', 'G');
      video_ = std::make_unique<cv::VideoWriter>(video_path_, fourcc, fps_, size_);
      if (!video_->isOpened()) throw InputError("--record " + target_ + ": no video encoder can write this file");
    }
    video_->write(bgr);
  } else {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06d.png", written_);
    writePngAtomically((fs::path(target_) / name).string(), bgr);
  }
  ++written_;
}

void FrameRecorder::finish() {
  if (finished_) return;
  finished_ = true;
  if (!isVideo()) return;
  if (!video_) throw InputError("--record " + target_ + ": no frame was recorded");
  video_->release();
  std::error_code ec;
  fs::rename(video_path_, target_, ec);
  if (ec) throw InputError("--record " + target_ + ": " + ec.message());
}

}  // namespace onetip::viewer
