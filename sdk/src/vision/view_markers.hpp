// vision/view_markers.hpp — the 2-D markers of one view, indexed by id.
//
// id = row * cols + col (core/pattern.hpp); point[id] in view pixel
// coordinates (after the view's flip, centres at integers), valid[id] = 1
// where the marker was measured in this frame, confidence[id] in 0..1 how
// well its grid neighbours agree with it (vision/grid_tracker.hpp; 1 where a
// producer does not grade). The same id in the left and right views is the
// stereo correspondence.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "core/pattern.hpp"

namespace onetip::vision {

struct ViewMarkers {
  int rows = 0;
  int cols = 0;
  std::vector<cv::Point2f> point;
  std::vector<std::uint8_t> valid;
  std::vector<float> confidence;

  ViewMarkers() = default;
  explicit ViewMarkers(const MarkerPattern& pattern)
      : rows(pattern.rows), cols(pattern.cols),
        point(static_cast<size_t>(pattern.count()), cv::Point2f(0, 0)),
        valid(static_cast<size_t>(pattern.count()), 0), confidence(static_cast<size_t>(pattern.count()), 1.0f) {}

  int size() const noexcept { return rows * cols; }
  int count() const noexcept {
    int n = 0;
    for (auto v : valid) n += v ? 1 : 0;
    return n;
  }
  bool has(int row, int col) const noexcept {
    return row >= 0 && col >= 0 && row < rows && col < cols && valid[static_cast<size_t>(row * cols + col)];
  }
  const cv::Point2f& at(int row, int col) const { return point[static_cast<size_t>(row * cols + col)]; }
  void set(int id, cv::Point2f p) {
    point[static_cast<size_t>(id)] = p;
    valid[static_cast<size_t>(id)] = 1;
  }
  void clear(int id) { valid[static_cast<size_t>(id)] = 0; }
};

}  // namespace onetip::vision
