#include "capture/video_source.hpp"

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace onetip::capture {

VideoSource::VideoSource(const std::string& path, FrameCheckOptions check)
    : path_(path), checker_(check) {
  // FFmpeg only: letting OpenCV probe every backend (GStreamer first) prints
  // warnings for non-videos and leaks inside GStreamer's plugin scan.
  if (!video_.open(path, cv::CAP_FFMPEG) || !video_.isOpened())
    throw InputError("input '" + path + "': not a readable video file");
  const double fps = video_.get(cv::CAP_PROP_FPS);
  if (fps > 0.0 && fps < 1e4) rate_hz_ = fps;
}

Frame VideoSource::next() {
  Frame f;
  if (ended_) return f;
  cv::Mat image;
  bool read = false;
  std::string failure;
  try {  // a decoder exception on damaged data ends the stream; it never reaches the caller
    read = video_.read(image) && !image.empty();
  } catch (const std::exception& e) {
    failure = e.what();
  }
  if (!read) {
    ended_ = true;
    video_.release();
    if (failure.empty()) return f;
    f.index = position_++;
    const std::string where = "frame " + std::to_string(f.index);
    return deliver(std::move(f), cv::Mat(), "cannot decode (" + failure + "); the video ends here", where);
  }
  f.index = position_++;
  const double ms = video_.get(cv::CAP_PROP_POS_MSEC);
  f.timestamp_s = ms > 0.0 ? ms / 1000.0 : static_cast<double>(f.index) / rate_hz_;
  cv::Mat grey;
  if (image.channels() == 3)
    cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  else if (image.channels() == 4)
    cv::cvtColor(image, grey, cv::COLOR_BGRA2GRAY);
  else
    grey = image;
  if (grey.depth() == CV_16U) grey.convertTo(grey, CV_8U, 1.0 / 256.0);
  const auto problem = checker_.problem(grey);
  const std::string where = "frame " + std::to_string(f.index);
  return deliver(std::move(f), std::move(grey), problem, where);
}

}  // namespace onetip::capture
