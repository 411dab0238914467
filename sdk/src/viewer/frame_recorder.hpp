// viewer/frame_recorder.hpp — records what the viewer shows.
//
// A target ending in .mp4 or .avi is a video (cv::VideoWriter, MPEG-4 part 2
// "mp4v" or MJPG, at `fps`), written to "<stem>.part<pid><ext>" beside it and
// renamed into place by finish(), so an interrupted run leaves no half
// video; any other target is a folder (created if missing) of PNG frames
// frame_000000.png, frame_000001.png, ..., each written atomically. Frames are
// 8-bit BGR, all of the first frame's size.
#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>
#include <string>

namespace onetip::viewer {

// Writes `bgr` as a PNG file at `path`, whole or not at all (core/atomic_file.hpp).
// Throws InputError when it cannot.
void writePngAtomically(const std::string& path, const cv::Mat& bgr);

class FrameRecorder {
 public:
  // Throws InputError when the target cannot be written or fps <= 0.
  FrameRecorder(std::string target, double fps);
  ~FrameRecorder();
  FrameRecorder(const FrameRecorder&) = delete;
  FrameRecorder& operator=(const FrameRecorder&) = delete;

  // Throws InputError for a frame of another size or type, or a write failure.
  void write(const cv::Mat& bgr);
  // Closes the video and moves it into place (PNG folders are complete already).
  void finish();
  int written() const noexcept { return written_; }
  bool isVideo() const noexcept { return !video_path_.empty(); }

 private:
  std::string target_;
  double fps_;
  std::string video_path_;  // the temporary video file, empty for PNG folders
  std::unique_ptr<cv::VideoWriter> video_;
  cv::Size size_;
  int written_ = 0;
  bool finished_ = false;
};

}  // namespace onetip::viewer
