#include "vision/grid_tracker.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "core/error.hpp"
#include "vision/grid_graph.hpp"
#include "vision/grid_prediction.hpp"
#include "vision/grid_recovery.hpp"

namespace onetip::vision {
namespace {

LatticeView lattice(const ViewMarkers& m) { return {m.rows, m.cols, &m.point, &m.valid}; }

GridResult failure(GridStatus status, const MarkerPattern& pattern, std::string message) {
  GridResult r;
  r.status = status;
  r.markers = ViewMarkers(pattern);
  r.lost = pattern.count();
  r.message = std::move(message);
  return r;
}

// Ids from the grid graph of one image's corners; the grid must span the pattern.
GridResult assignIds(const std::vector<Corner>& corners, const ViewHalf& view, const MarkerPattern& pattern) {
  const GridLabelling g = labelGrid(corners, view, pattern.rows, pattern.cols);
  if (g.labelled < 4) return failure(GridStatus::GridNotFound, pattern, "no checkerboard grid found among the corners");
  if (g.rows != pattern.rows || g.cols != pattern.cols) {
    return failure(g.rows <= pattern.rows && g.cols <= pattern.cols ? GridStatus::GridIncomplete : GridStatus::GridNotFound,
                   pattern,
                   "grid of " + std::to_string(g.rows) + " x " + std::to_string(g.cols) + " corners found, pattern has " +
                       std::to_string(pattern.rows) + " x " + std::to_string(pattern.cols));
  }
  GridResult r;
  r.status = GridStatus::Ok;
  r.markers = ViewMarkers(pattern);
  for (size_t i = 0; i < corners.size(); ++i)
    if (g.row[i] >= 0) r.markers.set(pattern.id(g.row[i], g.col[i]), corners[i].pt);
  r.found = r.markers.count();
  r.lost = pattern.count() - r.found;
  return r;
}

// Completes the points without `have` from their neighbours
// (grid_prediction.hpp), growing inwards into holes; sets `have` where filled.
void fillHoles(const MarkerPattern& pattern, std::vector<cv::Point2f>& point, std::vector<std::uint8_t>& have) {
  for (int pass = 0; pass < pattern.rows + pattern.cols; ++pass) {
    std::vector<std::pair<int, cv::Point2f>> filled;
    const LatticeView grid{pattern.rows, pattern.cols, &point, &have};
    for (int id = 0; id < pattern.count(); ++id) {
      if (have[static_cast<size_t>(id)]) continue;
      if (auto q = predictFromNeighbours(grid, pattern.rowOf(id), pattern.colOf(id))) filled.emplace_back(id, *q);
    }
    if (filled.empty()) return;
    for (const auto& [id, q] : filled) point[static_cast<size_t>(id)] = q, have[static_cast<size_t>(id)] = 1;
  }
}

}  // namespace

void GridTrackerOptions::validate() const {
  if (!(search_radius > 0.0f && search_radius < 0.5f)) throw InputError("grid_tracker.search_radius: must be in (0, 0.5)");
  if (!(outlier_fraction > 0.0f && outlier_fraction < 1.0f))
    throw InputError("grid_tracker.outlier_fraction: must be in (0, 1)");
  if (!(max_link_stretch > 1.0f)) throw InputError("grid_tracker.max_link_stretch: must exceed 1");
  if (!(recovery_reach > 0.0f && recovery_reach <= 3.0f)) throw InputError("grid_tracker.recovery_reach: must be in (0, 3]");
  if (!(velocity_gain >= 0.0f && velocity_gain <= 1.0f)) throw InputError("grid_tracker.velocity_gain: must be in 0..1");
}

GridTracker::GridTracker(MarkerPattern pattern, GridTrackerOptions options)
    : pattern_(pattern), options_(options) {
  pattern_.validate();
  options_.validate();
}

GridResult GridTracker::initialize(const std::vector<Corner>& corners, const ViewHalf& view) {
  if (view.raw.empty() || view.raw.type() != CV_8UC1) throw InputError("grid tracker: view must be a non-empty CV_8UC1 image");
  GridResult r = assignIds(corners, view, pattern_);
  initialized_ = r.ok();
  if (initialized_) {
    rest_ = current_ = r.markers;
    previous_ = ViewMarkers(pattern_);
  }
  return r;
}

GridResult GridTracker::initialize(const ViewHalf& view, const CornerDetector& detector) {
  return initialize(detectInView(detector, view), view);
}

GridTracker::Prediction GridTracker::predict() const {
  const int n = pattern_.count();
  Prediction p;
  p.point.assign(static_cast<size_t>(n), cv::Point2f(0, 0));
  p.radius.assign(static_cast<size_t>(n), 0.0f);
  std::vector<std::uint8_t> have(static_cast<size_t>(n), 0);
  for (int id = 0; id < n; ++id) {
    const size_t i = static_cast<size_t>(id);
    if (!current_.valid[i]) continue;
    p.point[i] = current_.point[i];
    if (previous_.valid[i]) p.point[i] += options_.velocity_gain * (current_.point[i] - previous_.point[i]);
    have[i] = 1;
  }
  // Lost markers: from the predicted neighbours, else their last estimate.
  fillHoles(pattern_, p.point, have);
  for (int id = 0; id < n; ++id)
    if (!have[static_cast<size_t>(id)]) p.point[static_cast<size_t>(id)] = current_.point[static_cast<size_t>(id)];
  // Search radius from the predicted local spacing (the rest spacing as fallback).
  const std::vector<std::uint8_t> all(static_cast<size_t>(n), 1);
  const LatticeView grid{pattern_.rows, pattern_.cols, &p.point, &all};
  const LatticeView rest = lattice(rest_);
  for (int id = 0; id < n; ++id) {
    const int r = pattern_.rowOf(id), c = pattern_.colOf(id);
    float spacing = localSpacing(grid, r, c, p.point[static_cast<size_t>(id)]);
    if (spacing <= 0) spacing = localSpacing(rest, r, c, rest_.point[static_cast<size_t>(id)]);
    p.radius[static_cast<size_t>(id)] = options_.search_radius * spacing;
  }
  return p;
}

GridResult GridTracker::track(const std::vector<Corner>& corners, const ViewHalf& view) {
  if (view.raw.empty() || view.raw.type() != CV_8UC1) throw InputError("grid tracker: view must be a non-empty CV_8UC1 image");
  if (!initialized_) return failure(GridStatus::NotInitialized, pattern_, "grid tracker: track() before a successful initialize()");
  const Prediction pred = predict();
  // Corners sorted by x for a range search around each prediction.
  std::vector<int> order(corners.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return corners[a].pt.x < corners[b].pt.x; });
  std::vector<float> xs(order.size());
  for (size_t k = 0; k < order.size(); ++k) xs[k] = corners[order[k]].pt.x;
  ViewMarkers candidates(pattern_);
  for (int id = 0; id < pattern_.count(); ++id) {
    const cv::Point2f q = pred.point[static_cast<size_t>(id)];
    const float radius = pred.radius[static_cast<size_t>(id)];
    float best = radius * radius;
    int arg = -1;
    for (auto k = std::lower_bound(xs.begin(), xs.end(), q.x - radius) - xs.begin();
         k < static_cast<long>(xs.size()) && xs[static_cast<size_t>(k)] <= q.x + radius; ++k) {
      const cv::Point2f d = corners[order[static_cast<size_t>(k)]].pt - q;
      if (d.dot(d) <= best) best = d.dot(d), arg = order[static_cast<size_t>(k)];
    }
    if (arg >= 0) candidates.set(id, corners[arg].pt);
  }
  if (candidates.count() < pattern_.count()) recover(corners, view, pred, candidates);
  return finish(pred, std::move(candidates));
}

GridResult GridTracker::track(const ViewHalf& view, const CornerDetector& detector) {
  if (!initialized_) return failure(GridStatus::NotInitialized, pattern_, "grid tracker: track() before a successful initialize()");
  if (view.raw.empty() || view.raw.type() != CV_8UC1) throw InputError("grid tracker: view must be a non-empty CV_8UC1 image");
  const Prediction pred = predict();
  ViewMarkers candidates(pattern_);
  const auto detect_start = std::chrono::steady_clock::now();
  for (int id = 0; id < pattern_.count(); ++id) {
    const size_t i = static_cast<size_t>(id);
    if (auto c = detector.detectNear(view.raw, view.toRaw(pred.point[i]), pred.radius[i])) candidates.set(id, view.toView(c->pt));
  }
  double detect_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - detect_start).count();
  if (candidates.count() < pattern_.count()) {
    // Detect in the region of the lost markers (raw pixels), for recovery.
    cv::Rect2f box;
    float reach = 0;
    for (int id = 0; id < pattern_.count(); ++id) {
      const size_t i = static_cast<size_t>(id);
      if (candidates.valid[i]) continue;
      const cv::Point2f p = view.toRaw(pred.point[i]);
      box = box.area() > 0 ? (box | cv::Rect2f(p, cv::Size2f(1, 1))) : cv::Rect2f(p, cv::Size2f(1, 1));
      reach = std::max(reach, 2.0f * pred.radius[i] / options_.search_radius);
    }
    const cv::Rect roi = cv::Rect(cv::Point(static_cast<int>(box.x - reach), static_cast<int>(box.y - reach)),
                                  cv::Point(static_cast<int>(box.br().x + reach), static_cast<int>(box.br().y + reach))) &
                         cv::Rect(0, 0, view.width(), view.height());
    if (roi.area() > 0) {
      const auto roi_start = std::chrono::steady_clock::now();
      std::vector<Corner> corners = detector.detect(view.raw(roi));
      detect_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - roi_start).count();
      for (Corner& c : corners) {
        c.pt += cv::Point2f(static_cast<float>(roi.x), static_cast<float>(roi.y));
        c = toView(c, view);
      }
      recover(corners, view, pred, candidates);
    }
  }
  GridResult result = finish(pred, std::move(candidates));
  result.detect_ms = detect_ms;
  return result;
}

void GridTracker::recover(const std::vector<Corner>& corners, const ViewHalf& view, const Prediction& pred,
                          ViewMarkers& candidates) const {
  std::vector<float> reach(pred.radius.size());
  for (size_t i = 0; i < reach.size(); ++i) reach[i] = options_.recovery_reach * pred.radius[i] / options_.search_radius;
  recoverThroughLinks(corners, view, pattern_, pred.point, reach, candidates);
}

GridResult GridTracker::finish(const Prediction& pred, ViewMarkers m) {
  GridResult r;
  const auto distance2 = [&](int id) {
    const cv::Point2f d = m.point[static_cast<size_t>(id)] - pred.point[static_cast<size_t>(id)];
    return d.dot(d);
  };
  // Two neighbouring ids on one corner: the one predicted nearer keeps it.
  for (int id = 0; id < pattern_.count(); ++id) {
    if (!m.valid[static_cast<size_t>(id)]) continue;
    const int row = pattern_.rowOf(id), col = pattern_.colOf(id);
    for (int dr = -1; dr <= 1; ++dr) {
      for (int dc = -1; dc <= 1; ++dc) {
        const int other = pattern_.id(row + dr, col + dc);
        if ((dr == 0 && dc == 0) || !m.has(row + dr, col + dc)) continue;
        const cv::Point2f d = m.point[static_cast<size_t>(other)] - m.point[static_cast<size_t>(id)];
        if (d.dot(d) < 1.0f) m.clear(distance2(id) <= distance2(other) ? other : id);
      }
    }
  }
  // Outliers: far from the neighbours' completion, or links that flip or stretch.
  const LatticeView now = lattice(m), before = lattice(current_);
  std::vector<int> reject;
  for (int id = 0; id < pattern_.count(); ++id) {
    if (!m.valid[static_cast<size_t>(id)]) continue;
    const int row = pattern_.rowOf(id), col = pattern_.colOf(id);
    const cv::Point2f p = m.point[static_cast<size_t>(id)];
    const float spacing = pred.radius[static_cast<size_t>(id)] / options_.search_radius;
    if (auto q = predictFromNeighbours(now, row, col)) {
      const cv::Point2f d = p - *q;
      if (d.dot(d) > options_.outlier_fraction * options_.outlier_fraction * spacing * spacing) {
        reject.push_back(id);
        continue;
      }
    }
    int checked = 0, bad = 0;
    constexpr int kDir[4][2] = {{0, 1}, {0, -1}, {1, 0}, {-1, 0}};
    for (const auto& k : kDir) {
      const int nr = row + k[0], nc = col + k[1];
      if (!now.has(nr, nc) || !before.has(nr, nc) || !before.has(row, col)) continue;
      const cv::Point2f link = now.at(nr, nc) - p, old = before.at(nr, nc) - before.at(row, col);
      const float ratio = std::sqrt(link.dot(link) / std::max(old.dot(old), 1e-6f));
      ++checked;
      if (link.dot(old) <= 0 || ratio > options_.max_link_stretch || ratio * options_.max_link_stretch < 1.0f) ++bad;
    }
    if (2 * bad > checked) reject.push_back(id);
  }
  for (int id : reject) m.clear(id);
  r.rejected = static_cast<int>(reject.size());

  // State update: the measured markers; the lost ones completed from this
  // frame's measured neighbours where possible, else their prediction.
  previous_ = current_;
  std::vector<cv::Point2f> estimate = m.point;
  std::vector<std::uint8_t> have = m.valid;
  fillHoles(pattern_, estimate, have);
  for (int id = 0; id < pattern_.count(); ++id) {
    const size_t i = static_cast<size_t>(id);
    if (m.valid[i] && !previous_.valid[i]) ++r.recovered;
    current_.valid[i] = m.valid[i];
    current_.point[i] = have[i] ? estimate[i] : pred.point[i];
  }
  r.markers = std::move(m);
  r.found = r.markers.count();
  r.lost = pattern_.count() - r.found;
  r.status = r.found >= 3 ? GridStatus::Ok : GridStatus::Lost;
  if (!r.ok()) r.message = "grid tracker: only " + std::to_string(r.found) + " markers found";
  return r;
}

GridResult detectBoard(const cv::Mat& grey, const MarkerPattern& pattern, const CornerDetectorOptions& options) {
  return detectBoard(ViewHalf{grey, false}, pattern, options);
}

GridResult detectBoard(const ViewHalf& view, const MarkerPattern& pattern, const CornerDetectorOptions& options) {
  pattern.validate();
  const CornerDetector detector(options);
  return assignIds(detectInView(detector, view), view, pattern);
}

}  // namespace onetip::vision
