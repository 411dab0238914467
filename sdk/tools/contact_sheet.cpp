#include "contact_sheet.hpp"

#include <algorithm>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace onetip::tools {

ContactSheet::ContactSheet(int frame_count, int tiles, int columns, int tile_width)
    : frame_count_(std::max(1, frame_count)), tiles_(std::max(1, std::min(tiles, frame_count))),
      columns_(std::max(1, columns)), tile_width_(tile_width) {}

bool ContactSheet::wants(int k) const {
  if (tiles_ <= 1) return k == 0;
  // tile t shows frame round(t * (n - 1) / (tiles - 1))
  for (int t = 0; t < tiles_; ++t)
    if (k == static_cast<int>(std::lround(double(t) * (frame_count_ - 1) / (tiles_ - 1)))) return true;
  return false;
}

void ContactSheet::add(const cv::Mat& frame, const std::vector<std::string>& caption) {
  cv::Mat bgr, tile;
  if (frame.channels() == 1)
    cv::cvtColor(frame, bgr, cv::COLOR_GRAY2BGR);
  else
    bgr = frame;
  const int h = std::max(1, frame.rows * tile_width_ / std::max(1, frame.cols));
  cv::resize(bgr, tile, {tile_width_, h}, 0, 0, cv::INTER_AREA);
  int y = 18;
  for (const auto& line : caption) {
    cv::putText(tile, line, {8, y}, cv::FONT_HERSHEY_SIMPLEX, 0.45, {0, 0, 0}, 3, cv::LINE_AA);
    cv::putText(tile, line, {8, y}, cv::FONT_HERSHEY_SIMPLEX, 0.45, {80, 255, 255}, 1, cv::LINE_AA);
    y += 18;
  }
  images_.push_back(tile);
}

void ContactSheet::save(const std::string& path) const {
  const std::vector<uchar> png = this->png(path);
  AtomicFile file(path);
  file.stream().write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  file.commit();
}

std::vector<unsigned char> ContactSheet::png(const std::string& path) const {
  if (images_.empty()) throw InputError(path + ": no frames for the contact sheet");
  const int rows = (static_cast<int>(images_.size()) + columns_ - 1) / columns_;
  const int th = images_.front().rows;
  cv::Mat sheet(rows * th, columns_ * tile_width_, CV_8UC3, cv::Scalar(30, 30, 30));
  for (size_t i = 0; i < images_.size(); ++i) {
    const int r = static_cast<int>(i) / columns_, c = static_cast<int>(i) % columns_;
    images_[i].copyTo(sheet(cv::Rect(c * tile_width_, r * th, tile_width_, std::min(th, images_[i].rows))));
  }
  std::vector<uchar> png;
  if (!cv::imencode(".png", sheet, png)) throw InputError(path + ": cannot encode the contact sheet");
  return png;
}

}  // namespace onetip::tools
