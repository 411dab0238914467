// vision/grid_growth.hpp — one frame's markers grown over the grid graph from
// the markers that stood still, each predicted from its found neighbours'
// motion in this frame.
//
// The pad's deformation field is smooth, so a marker moves almost as its grid
// neighbours do, whatever its own history (a reversal, a sudden start):
//  1. seeds: markers measured in the last frame whose last motion was at most
//     seed_speed x spacing are searched at last + velocity_gain x motion
//     within seed_radius x spacing;
//  2. growth: in passes, each marker not yet found that has found
//     8-neighbours (the best-connected first) is searched at
//     predictFromNeighbourMotion (below) within search_radius x spacing, and
//     where nothing is found there and its motion is known, once more at
//     predictFromOwnTrack (below: a marker sliding past neighbours that stick
//     keeps its own velocity); a marker is searched at most max_attempts
//     times, again only once more of its neighbours are found;
//  3. markers no growth reaches (no found neighbour) are searched at their
//     own temporal prediction (last + velocity_gain x motion), and growth
//     continues from those found.
// A wrong seed needs a marker that stood still to jump more than
// 1 - seed_radius squares in one frame. Units: view pixels; spacing per id is
// the local marker spacing in pixels.
#pragma once

#include <cstdint>
#include <functional>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "core/pattern.hpp"
#include "vision/view_markers.hpp"

namespace onetip::vision {

struct GrowthOptions {
  float seed_speed = 0.1f;     // of spacing per frame: slower markers seed the growth
  float seed_radius = 0.2f;    // of spacing: a seed's search radius
  float search_radius = 0.4f;  // of spacing: a grown marker's search radius
  float velocity_gain = 0.5f;  // temporal prediction: last + gain x last motion
  int max_attempts = 2;        // searches per marker and frame during growth
};

struct GrowthState {
  const std::vector<cv::Point2f>* last = nullptr;     // per id: last known position
  const std::vector<std::uint8_t>* measured = nullptr;  // per id: measured in the last frame
  const std::vector<cv::Point2f>* motion = nullptr;   // per id: last frame's motion (0 where unknown)
  const std::vector<std::uint8_t>* moving = nullptr;  // per id: motion known (measured in the last two frames)
  const std::vector<float>* spacing = nullptr;        // per id: local spacing, pixels
};

// The corner nearest `guess` within `radius` pixels, if any.
using CornerFinder = std::function<std::optional<cv::Point2f>(cv::Point2f guess, float radius)>;

struct GrowthResult {
  ViewMarkers markers;  // found this frame
  int seeds = 0;        // markers found as seeds
};

// Where the neighbours' motion in this frame puts marker `id`:
//   last[id] + median over found 8-neighbours nb of m(nb),
// m(nb) = now[nb] - last[nb], extrapolated linearly along the lattice line
// (2 m(nb) - m(nb2)) when the next marker nb2 on it is found too; the median
// is component-wise, so one wrong neighbour cannot move it far. With
// measured_only, only neighbours measured in the last frame count. Nothing
// when no neighbour counts.
std::optional<cv::Point2f> predictFromNeighbourMotion(const MarkerPattern& pattern, const std::vector<cv::Point2f>& last,
                                                      const std::vector<std::uint8_t>& measured, const ViewMarkers& now,
                                                      int id, bool measured_only);

// Where its own track puts marker `id`, its velocity corrected by the change
// of its neighbours' motion in this frame:
//   last[id] + m(id) + median over found 8-neighbours nb with known motion of
//   (now[nb] - last[nb] - m(nb)),
// m: the last frame's motion; the median component-wise. A marker that slides
// on while its neighbours stick (or sticks while they slide) keeps its own
// motion, which their motion alone cannot give; a reversal or a stop of the
// whole field moves it with them. Nothing when the motion of `id` or of every
// found neighbour is unknown.
std::optional<cv::Point2f> predictFromOwnTrack(const MarkerPattern& pattern, const std::vector<cv::Point2f>& last,
                                               const std::vector<cv::Point2f>& motion,
                                               const std::vector<std::uint8_t>& moving, const ViewMarkers& now, int id);

GrowthResult growGrid(const MarkerPattern& pattern, const GrowthState& state, const GrowthOptions& options,
                      const CornerFinder& find);

}  // namespace onetip::vision
