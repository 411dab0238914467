#include "vision/view_shift.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/error.hpp"
#include "core/median.hpp"
#include "core/option_checks.hpp"

namespace onetip::vision {

void ViewShiftOptions::validate() const {
  requireInRange("view shift: move_sigmas", move_sigmas, 3, 1000);
  requireInRange("view shift: min_sigma_px", min_sigma_px, 0.001, 1, "px");
  if (min_corners < 3 || min_corners > 10000) throw InputError("view shift: min_corners: must be in [3, 10000]");
  requireInRange("view shift: report_px", report_px, 0, 100, "px");
}

ViewShiftKeeper::ViewShiftKeeper(bool flip_left, bool flip_right, ViewShiftOptions options)
    : flip_{flip_left, flip_right}, options_(options) {
  options_.validate();
}

void ViewShiftKeeper::reset() {
  offset_[0] = offset_[1] = unreported_[0] = unreported_[1] = cv::Point2d(0, 0);
}

namespace {

// One view's common translation t (view px) against its rest, the noise sigma of the corners about it, and
// whether every corner lies within bound of t.
struct ViewMotion {
  bool measured = false;
  cv::Point2d t;
  double sigma = 0;    // of one corner (px)
  double t_sd = 0;     // of the median t (px)
  bool together = false;
};

ViewMotion viewMotion(const ViewMarkers& rest, const ViewMarkers& now, const cv::Point2d& offset,
                      const ViewShiftOptions& o) {
  ViewMotion m;
  std::vector<cv::Point2d> d;
  for (size_t i = 0; i < now.point.size() && i < rest.point.size(); ++i)
    if (now.valid[i] && rest.valid[i])
      d.emplace_back(now.point[i].x - offset.x - rest.point[i].x, now.point[i].y - offset.y - rest.point[i].y);
  if (static_cast<int>(d.size()) < o.min_corners) return m;
  std::vector<double> xs, ys;
  for (const auto& p : d) {
    xs.push_back(p.x);
    ys.push_back(p.y);
  }
  m.t = {upperMedian(xs), upperMedian(ys)};
  std::vector<double> abs_e;
  for (const auto& p : d) {
    abs_e.push_back(std::abs(p.x - m.t.x));
    abs_e.push_back(std::abs(p.y - m.t.y));
  }
  m.sigma = std::max(1.4826 * upperMedian(abs_e), o.min_sigma_px);
  m.t_sd = 1.2533 * m.sigma / std::sqrt(static_cast<double>(d.size()));
  const double bound = o.move_sigmas * m.sigma;
  m.together = std::all_of(d.begin(), d.end(), [&](const cv::Point2d& p) { return cv::norm(p - m.t) <= bound; });
  m.measured = true;
  return m;
}

}  // namespace

ViewShiftUpdate ViewShiftKeeper::update(const ViewMarkers& rest_left, const ViewMarkers& rest_right,
                                        const ViewMarkers& now_left, const ViewMarkers& now_right) {
  ViewShiftUpdate out;
  const ViewMotion v[2] = {viewMotion(rest_left, now_left, offset_[0], options_),
                           viewMotion(rest_right, now_right, offset_[1], options_)};
  if (!v[0].measured || !v[1].measured) return out;
  bool moved[2];
  for (int k = 0; k < 2; ++k) moved[k] = v[k].together && cv::norm(v[k].t) > options_.move_sigmas * v[k].t_sd;
  if (!moved[0] && !moved[1]) return out;
  // A view that moved while the other's corners did not all stay together is not told from a touch.
  for (int k = 0; k < 2; ++k)
    if (moved[k] && !moved[1 - k] && !v[1 - k].together) return out;
  if (moved[0] && moved[1]) {
    const auto delivered = [&](int k) { return cv::Point2d(flip_[k] ? -v[k].t.x : v[k].t.x, v[k].t.y); };
    const double bound = options_.move_sigmas * std::hypot(v[0].t_sd, v[1].t_sd);
    if (cv::norm(delivered(0) - delivered(1)) > bound) return out;  // the disparity changed: the pad moved
  }
  for (int k = 0; k < 2; ++k)
    if (moved[k]) {
      offset_[k] += v[k].t;
      unreported_[k] += v[k].t;
    }
  out.corrected = true;
  const bool camera = moved[0] && moved[1];
  const int k = moved[0] ? 0 : 1;  // the view whose correction is reported (the left one for the camera)
  if (cv::norm(unreported_[k]) >= options_.report_px) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "%s moved against the pad by (%.2f, %.2f) px in the %s view: corrected",
                  camera ? "the camera" : (k == 0 ? "the left mirror" : "the right mirror"), unreported_[k].x,
                  unreported_[k].y, k == 0 ? "left" : "right");
    out.report = buf;
    unreported_[k] = cv::Point2d(0, 0);
    if (camera) unreported_[1 - k] = cv::Point2d(0, 0);
  }
  return out;
}

void ViewShiftKeeper::correct(ViewMarkers& left, ViewMarkers& right) const {
  ViewMarkers* views[2] = {&left, &right};
  for (int v = 0; v < 2; ++v) {
    if (offset_[v].x == 0 && offset_[v].y == 0) continue;
    const cv::Point2f o(static_cast<float>(offset_[v].x), static_cast<float>(offset_[v].y));
    for (cv::Point2f& p : views[v]->point) p -= o;
  }
}

}  // namespace onetip::vision
