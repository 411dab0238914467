// vision/grid_prediction.hpp — a marker's position from its grid neighbours.
//
// For marker (r, c) of a rows x cols lattice of 2-D points (view pixels) with
// a per-marker flag, each available completion estimates its position:
// midpoints of opposite neighbours, (p[r,c-1] + p[r,c+1]) / 2 and likewise
// along rows; linear extrapolations 2 p[r,c-1] - p[r,c-2] (four directions);
// parallelogram completions p[r+dr,c] + p[r,c+dc] - p[r+dr,c+dc]
// (dr, dc = +-1). The estimate is their component-wise median, which one bad
// neighbour cannot move far. Exact for any affine map of the lattice.
// closeCompletion: the largest distance from p to the midpoint and
// parallelogram completions of (r, c) (no extrapolations, which the lattice's
// curvature moves), or nothing with fewer than three of them or no midpoint
// (each parallelogram spans both lattice axes, so three completions with a
// midpoint tie p to neighbours along both): a tight bound means p sits where
// its neighbours agree to put it.
// localSpacing: median distance from p[r,c] to its available 4-neighbours;
// shortestLink: the smallest of those distances (where a view foreshortens
// the lattice along one axis, the spacing that bounds a safe search).
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

namespace onetip::vision {

struct LatticeView {
  int rows = 0, cols = 0;
  const std::vector<cv::Point2f>* point = nullptr;
  const std::vector<std::uint8_t>* valid = nullptr;

  bool has(int r, int c) const noexcept {
    return r >= 0 && c >= 0 && r < rows && c < cols && (*valid)[static_cast<size_t>(r * cols + c)];
  }
  const cv::Point2f& at(int r, int c) const { return (*point)[static_cast<size_t>(r * cols + c)]; }
};

// Median of the neighbour completions of (r, c), or nothing without any.
std::optional<cv::Point2f> predictFromNeighbours(const LatticeView& grid, int r, int c);

// Largest distance from `p` to the midpoint and parallelogram completions of
// (r, c); nothing with fewer than three or without a midpoint.
std::optional<float> closeCompletion(const LatticeView& grid, int r, int c, cv::Point2f p);

// Median distance from `p` to the available 4-neighbours of (r, c), or 0.
float localSpacing(const LatticeView& grid, int r, int c, cv::Point2f p);

// Smallest distance from `p` to the available 4-neighbours of (r, c), or 0.
float shortestLink(const LatticeView& grid, int r, int c, cv::Point2f p);

}  // namespace onetip::vision
