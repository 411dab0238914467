#include "vision/grid_tracker.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "core/error.hpp"
#include "vision/grid_checks.hpp"
#include "vision/grid_graph.hpp"
#include "vision/grid_growth.hpp"
#include "vision/grid_prediction.hpp"
#include "vision/grid_recovery.hpp"
#include "vision/grid_rescue.hpp"

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
  if (!(spatial_outlier_fraction >= outlier_fraction && spatial_outlier_fraction < 1.0f))
    throw InputError("grid_tracker.spatial_outlier_fraction: must be in [outlier_fraction, 1)");
  if (!(max_link_stretch > 1.0f)) throw InputError("grid_tracker.max_link_stretch: must exceed 1");
  if (!(recovery_reach > 0.0f && recovery_reach <= 3.0f)) throw InputError("grid_tracker.recovery_reach: must be in (0, 3]");
  if (!(velocity_gain >= 0.0f && velocity_gain <= 1.0f)) throw InputError("grid_tracker.velocity_gain: must be in 0..1");
  if (!(seed_speed >= 0.0f && seed_speed <= 1.0f)) throw InputError("grid_tracker.seed_speed: must be in 0..1");
  if (!(seed_radius > 0.0f && seed_radius <= search_radius))
    throw InputError("grid_tracker.seed_radius: must be in (0, search_radius]");
  if (min_seeds < 1) throw InputError("grid_tracker.min_seeds: must be at least 1");
  if (!(relabel_median > 0.0f && relabel_median < 1.0f)) throw InputError("grid_tracker.relabel_median: must be in (0, 1)");
  if (!(seam_stretch > 1.0f && seam_stretch < 2.0f)) throw InputError("grid_tracker.seam_stretch: must be in (1, 2)");
  if (!(rescue_fraction >= 0.0f && rescue_fraction <= outlier_fraction))
    throw InputError("grid_tracker.rescue_fraction: must be in [0, outlier_fraction]");
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
    carried_.assign(static_cast<size_t>(pattern_.count()), 0);
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
  p.spacing.assign(static_cast<size_t>(n), 0.0f);
  p.motion.assign(static_cast<size_t>(n), cv::Point2f(0, 0));
  p.moving.assign(static_cast<size_t>(n), 0);
  std::vector<std::uint8_t> have(static_cast<size_t>(n), 0);
  for (int id = 0; id < n; ++id) {
    const size_t i = static_cast<size_t>(id);
    if (!current_.valid[i]) continue;
    if (previous_.valid[i]) p.motion[i] = current_.point[i] - previous_.point[i], p.moving[i] = 1;
    p.point[i] = current_.point[i] + options_.velocity_gain * p.motion[i];
    have[i] = 1;
  }
  // Lost markers: from the predicted neighbours, else their last estimate.
  fillHoles(pattern_, p.point, have);
  for (int id = 0; id < n; ++id)
    if (!have[static_cast<size_t>(id)]) p.point[static_cast<size_t>(id)] = current_.point[static_cast<size_t>(id)];
  // Local spacing and search radius from the predicted links (the rest ones
  // as fallback); the radius from the shortest link, so a foreshortened axis
  // cannot bring the neighbour along it inside.
  const std::vector<std::uint8_t> all(static_cast<size_t>(n), 1);
  const LatticeView grid{pattern_.rows, pattern_.cols, &p.point, &all};
  const LatticeView rest = lattice(rest_);
  for (int id = 0; id < n; ++id) {
    const int r = pattern_.rowOf(id), c = pattern_.colOf(id);
    const size_t i = static_cast<size_t>(id);
    float shortest = shortestLink(grid, r, c, p.point[i]), spacing = localSpacing(grid, r, c, p.point[i]);
    if (shortest <= 0) shortest = shortestLink(rest, r, c, rest_.point[i]), spacing = localSpacing(rest, r, c, rest_.point[i]);
    p.radius[i] = options_.search_radius * shortest;
    p.spacing[i] = spacing;
  }
  return p;
}

GridResult GridTracker::track(const std::vector<Corner>& corners, const ViewHalf& view) {
  if (view.raw.empty() || view.raw.type() != CV_8UC1) throw InputError("grid tracker: view must be a non-empty CV_8UC1 image");
  if (!initialized_) return failure(GridStatus::NotInitialized, pattern_, "grid tracker: track() before a successful initialize()");
  // Corners sorted by x for a range search around each prediction.
  std::vector<int> order(corners.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return corners[a].pt.x < corners[b].pt.x; });
  std::vector<float> xs(order.size());
  for (size_t k = 0; k < order.size(); ++k) xs[k] = corners[order[k]].pt.x;
  const auto near = [&](cv::Point2f q, float radius) -> std::optional<cv::Point2f> {
    float best = radius * radius;
    int arg = -1;
    for (auto k = std::lower_bound(xs.begin(), xs.end(), q.x - radius) - xs.begin();
         k < static_cast<long>(xs.size()) && xs[static_cast<size_t>(k)] <= q.x + radius; ++k) {
      const cv::Point2f d = corners[order[static_cast<size_t>(k)]].pt - q;
      if (d.dot(d) <= best) best = d.dot(d), arg = order[static_cast<size_t>(k)];
    }
    if (arg < 0) return std::nullopt;
    return corners[static_cast<size_t>(arg)].pt;
  };
  return trackWith(near, [&](const std::vector<cv::Point2f>&, float) { return corners; }, view);
}

GridResult GridTracker::track(const ViewHalf& view, const CornerDetector& detector) {
  if (!initialized_) return failure(GridStatus::NotInitialized, pattern_, "grid tracker: track() before a successful initialize()");
  if (view.raw.empty() || view.raw.type() != CV_8UC1) throw InputError("grid tracker: view must be a non-empty CV_8UC1 image");
  double detect_ms = 0;
  const auto timed = [&](auto&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    auto out = f();
    detect_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return out;
  };
  // Every marker's window asked for at once: a fresh frame is not in the cache.
  std::vector<cv::Point2f> last_raw(current_.point.size());
  for (size_t i = 0; i < last_raw.size(); ++i) last_raw[i] = view.toRaw(current_.point[i]);
  detector.prefetchNear(view.raw, last_raw);
  const auto near = [&](cv::Point2f q, float radius) -> std::optional<cv::Point2f> {
    const auto c = timed([&] { return detector.detectNear(view.raw, view.toRaw(q), radius); });
    if (!c) return std::nullopt;
    return view.toView(c->pt);
  };
  // Detection in the raw bounding box of the points, grown by `reach`.
  const auto region = [&](const std::vector<cv::Point2f>& points, float reach) {
    std::vector<Corner> corners;
    if (points.empty()) return corners;
    cv::Rect2f box;
    for (const cv::Point2f& q : points) {
      const cv::Point2f p = view.toRaw(q);
      box = box.area() > 0 ? (box | cv::Rect2f(p, cv::Size2f(1, 1))) : cv::Rect2f(p, cv::Size2f(1, 1));
    }
    const cv::Rect roi = cv::Rect(cv::Point(static_cast<int>(box.x - reach), static_cast<int>(box.y - reach)),
                                  cv::Point(static_cast<int>(box.br().x + reach), static_cast<int>(box.br().y + reach))) &
                         cv::Rect(0, 0, view.width(), view.height());
    if (roi.area() <= 0) return corners;
    corners = timed([&] { return detector.detect(view.raw(roi)); });
    for (Corner& c : corners) {
      c.pt += cv::Point2f(static_cast<float>(roi.x), static_cast<float>(roi.y));
      c = toView(c, view);
    }
    return corners;
  };
  GridResult result = trackWith(near, region, view);
  result.detect_ms = detect_ms;
  return result;
}

GridResult GridTracker::trackWith(const std::function<std::optional<cv::Point2f>(cv::Point2f, float)>& near,
                                  const RegionDetector& region, const ViewHalf& view) {
  const Prediction pred = predict();
  const size_t n = static_cast<size_t>(pattern_.count());
  std::vector<float> shortest(n);  // the growth's searches scale with the shortest link
  for (size_t i = 0; i < n; ++i) shortest[i] = pred.radius[i] / options_.search_radius;
  const std::vector<float>& spacing = pred.spacing;
  std::vector<float> sorted = spacing;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(n / 2), sorted.end());
  const float median_spacing = sorted[n / 2];  // reach of the whole-view detections
  const GrowthOptions growth{options_.seed_speed, options_.seed_radius, options_.search_radius, options_.velocity_gain, 2};
  const GrowthState state{&current_.point, &current_.valid, &pred.motion, &pred.moving, &shortest};
  GrowthResult grown = growGrid(pattern_, state, growth, near);
  ViewMarkers candidates = std::move(grown.markers);
  bool relabelled = false;
  if (grown.seeds < options_.min_seeds) {
    // Nothing stood still to grow from: the whole view, relabelled.
    ViewMarkers fresh(pattern_);
    const std::vector<Corner> corners = region(current_.point, median_spacing);
    if (relabelAnchored(corners, view, pattern_, current_.point, options_.relabel_median * median_spacing, fresh) >
        candidates.count())
      candidates = std::move(fresh), relabelled = true;
  }
  if (candidates.count() < pattern_.count()) {
    // Lost markers: completed from this frame's markers, else their temporal
    // prediction; recovered through the links of the corners around them.
    std::vector<cv::Point2f> expected = candidates.point;
    std::vector<std::uint8_t> have = candidates.valid;
    fillHoles(pattern_, expected, have);
    // Searched first where this frame's markers complete it (the growth
    // searched where their motion put it), unless that is within half a
    // square of the view's edge; finish() tests it like any other.
    const cv::Rect2f inner(0, 0, static_cast<float>(view.width()), static_cast<float>(view.height()));
    for (size_t i = 0; i < n; ++i) {
      const float m = 0.5f * spacing[i];
      const cv::Rect2f safe(inner.x + m, inner.y + m, inner.width - 2 * m, inner.height - 2 * m);
      if (candidates.valid[i] || !have[i] || !safe.contains(expected[i])) continue;
      if (const auto c = near(expected[i], pred.radius[i])) candidates.point[i] = *c, candidates.valid[i] = 1;
    }
    std::vector<cv::Point2f> lost;
    std::vector<float> reach(n);
    float widest = 0;
    for (size_t i = 0; i < n; ++i) {
      if (!have[i]) expected[i] = pred.point[i];
      reach[i] = options_.recovery_reach * spacing[i];
      if (!candidates.valid[i]) lost.push_back(expected[i]), widest = std::max(widest, 2.0f * spacing[i]);
    }
    recoverThroughLinks(region(lost, widest), view, pattern_, expected, reach, candidates);
  }
  if (hasSeam(candidates, options_.seam_stretch, near)) {
    // Ids slipped by a square somewhere: the whole view relabelled by the majority.
    relabelled = relabelByMajority(region(current_.point, median_spacing), view, pattern_, candidates) > 0 || relabelled;
  }
  GridResult r = finish(pred, std::move(candidates));
  r.relabelled = relabelled;
  return r;
}

GridResult GridTracker::finish(const Prediction& pred, ViewMarkers m) {
  GridResult r;
  const size_t n = static_cast<size_t>(pattern_.count());
  // Where the neighbours put each id (else its temporal prediction).
  const auto expected = [&](int id) {
    const auto q = predictFromNeighbours(lattice(m), pattern_.rowOf(id), pattern_.colOf(id));
    return q ? *q : pred.point[static_cast<size_t>(id)];
  };
  const auto distance2 = [&](int id) {
    const cv::Point2f d = m.point[static_cast<size_t>(id)] - expected(id);
    return d.dot(d);
  };
  // Two neighbouring ids on one corner: the one its neighbours predict better keeps it.
  for (int id = 0; id < pattern_.count(); ++id) {
    if (!m.valid[static_cast<size_t>(id)]) continue;
    const int row = pattern_.rowOf(id), col = pattern_.colOf(id);
    for (int dr = -1; dr <= 1; ++dr) {
      for (int dc = -1; dc <= 1; ++dc) {
        const int other = pattern_.id(row + dr, col + dc);
        if ((dr == 0 && dc == 0) || !m.has(row + dr, col + dc) || !m.valid[static_cast<size_t>(id)]) continue;
        const cv::Point2f d = m.point[static_cast<size_t>(other)] - m.point[static_cast<size_t>(id)];
        if (d.dot(d) < 1.0f) m.clear(distance2(id) <= distance2(other) ? other : id);
      }
    }
  }
  // Swap detector: far from where the neighbours put it, links that flip,
  // stretch or cross.
  const LatticeView now = lattice(m), before = lattice(current_);
  std::vector<int> reject;
  std::vector<OffMotion> off_motion;
  std::vector<float> confidence(n, 0.0f);
  for (int id = 0; id < pattern_.count(); ++id) {
    if (!m.valid[static_cast<size_t>(id)]) continue;
    const int row = pattern_.rowOf(id), col = pattern_.colOf(id);
    const cv::Point2f p = m.point[static_cast<size_t>(id)];
    const float tolerance = options_.outlier_fraction * pred.spacing[static_cast<size_t>(id)];
    // Residual against the neighbours' motion since the last frame when this
    // marker was measured then (robust to the pattern's own distortion), else
    // against their spatial completion; and, looser, against the spatial
    // completion always (a run of markers shifted together along a line
    // keeps its motion but not its place among the neighbours).
    const auto spatial = predictFromNeighbours(now, row, col);
    if (spatial && cv::norm(p - *spatial) > options_.spatial_outlier_fraction * tolerance / options_.outlier_fraction) {
      reject.push_back(id);
      continue;
    }
    std::optional<cv::Point2f> q;
    if (current_.valid[static_cast<size_t>(id)] || carried_[static_cast<size_t>(id)])
      q = predictFromNeighbourMotion(pattern_, current_.point, current_.valid, m, id, true);
    if (!q) q = spatial;
    float agreement = 0.5f;
    if (q) {
      const float residual = static_cast<float>(cv::norm(p - *q));
      if (residual > tolerance) {
        const auto own = predictFromOwnTrack(pattern_, current_.point, pred.motion, pred.moving, m, id);
        const float spacing = pred.spacing[static_cast<size_t>(id)];
        reject.push_back(id);
        const float track = own ? static_cast<float>(cv::norm(p - *own)) / spacing : kNoTrack;
        off_motion.push_back({id, residual / spacing, track});
        continue;
      }
      agreement = 1.0f - residual / tolerance;
    }
    const LinkCheck links = checkLinks(now, before, row, col, options_.max_link_stretch);
    if (2 * links.bad > links.checked || links.crossed > 0) {
      reject.push_back(id);
      continue;
    }
    confidence[static_cast<size_t>(id)] =
        agreement * (links.checked > 0 ? 1.0f - static_cast<float>(links.bad) / static_cast<float>(links.checked) : 1.0f);
  }
  rescueOffMotion(pattern_, m, before, pred.spacing, off_motion,
                  RescueLimits{options_.rescue_fraction, options_.max_link_stretch}, reject, confidence);
  for (int id : reject) m.clear(id);
  r.rejected = static_cast<int>(reject.size());
  m.confidence = std::move(confidence);

  // State update: the measured markers; those lost this frame carried by
  // their measured neighbours' motion (header), the other lost ones
  // completed from this frame's measured neighbours where possible, else
  // their prediction.
  previous_ = current_;
  std::vector<cv::Point2f> estimate = m.point;
  std::vector<std::uint8_t> have = m.valid;
  std::vector<std::uint8_t> carried(n, 0);
  for (int id = 0; id < pattern_.count(); ++id) {
    const size_t i = static_cast<size_t>(id);
    if (m.valid[i] || !previous_.valid[i]) continue;
    if (const auto q = predictFromNeighbourMotion(pattern_, previous_.point, previous_.valid, m, id, true))
      estimate[i] = *q, have[i] = 1, carried[i] = 1;
  }
  fillHoles(pattern_, estimate, have);
  for (int id = 0; id < pattern_.count(); ++id) {
    const size_t i = static_cast<size_t>(id);
    if (m.valid[i] && !previous_.valid[i]) ++r.recovered;
    current_.valid[i] = m.valid[i];
    current_.point[i] = have[i] ? estimate[i] : pred.point[i];
  }
  carried_ = std::move(carried);
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
