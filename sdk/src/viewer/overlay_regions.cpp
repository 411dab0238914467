#include "viewer/overlay_regions.hpp"

#include <algorithm>
#include <opencv2/core.hpp>
#include <stdexcept>

namespace onetip::viewer {

namespace {
// Horizontal runs of tiles in one band whose column-wise maximum (BGRA) has a non-zero alpha.
std::vector<cv::Rect> runsInBand(const cv::Mat& column_max, int tile, int y0, int height) {
  const int width = column_max.cols, tiles = (width + tile - 1) / tile;
  const auto* bgra = column_max.ptr<cv::Vec4b>(0);
  auto has_content = [&](int t) {
    const int x1 = std::min(width, (t + 1) * tile);
    return std::any_of(bgra + t * tile, bgra + x1, [](const cv::Vec4b& p) { return p[3] != 0; });
  };
  std::vector<cv::Rect> runs;
  for (int t = 0; t < tiles;) {
    if (!has_content(t)) {
      ++t;
      continue;
    }
    const int first = t;
    while (t < tiles && has_content(t)) ++t;
    runs.emplace_back(first * tile, y0, std::min(width, t * tile) - first * tile, height);
  }
  return runs;
}
}  // namespace

std::vector<cv::Rect> overlayRegions(const cv::Mat& bgra, int tile) {
  if (bgra.empty() || bgra.type() != CV_8UC4) throw std::invalid_argument("overlayRegions: expected a non-empty CV_8UC4 image");
  if (tile < 1) throw std::invalid_argument("overlayRegions: tile must be >= 1");
  cv::Mat column_max;
  std::vector<cv::Rect> closed, open;  // open: rectangles reaching the previous band's bottom
  for (int y0 = 0; y0 < bgra.rows; y0 += tile) {
    const int height = std::min(tile, bgra.rows - y0);
    cv::reduce(bgra.rowRange(y0, y0 + height), column_max, 0, cv::REDUCE_MAX);
    std::vector<cv::Rect> next;
    for (const cv::Rect& run : runsInBand(column_max, tile, y0, height)) {
      const auto above = std::find_if(open.begin(), open.end(),
                                      [&](const cv::Rect& r) { return r.x == run.x && r.width == run.width; });
      if (above == open.end()) {
        next.push_back(run);
        continue;
      }
      next.emplace_back(above->x, above->y, above->width, above->height + height);
      open.erase(above);
    }
    closed.insert(closed.end(), open.begin(), open.end());
    open = std::move(next);
  }
  closed.insert(closed.end(), open.begin(), open.end());
  return closed;
}

}  // namespace onetip::viewer
