#include "vision/grid_growth.hpp"

#include <algorithm>
#include <array>

namespace onetip::vision {
namespace {

// Median of the first n (at most 8) values, reordering them.
float median8(std::array<float, 8>& v, size_t n) {
  for (size_t a = 1; a < n; ++a)  // insertion sort: at most 8 values
    for (size_t b = a; b > 0 && v[b - 1] > v[b]; --b) std::swap(v[b - 1], v[b]);
  return n % 2 ? v[n / 2] : 0.5f * (v[n / 2 - 1] + v[n / 2]);
}

class Grower {
 public:
  Grower(const MarkerPattern& pattern, const GrowthState& state, const GrowthOptions& options, const CornerFinder& find)
      : p_(pattern), s_(state), o_(options), find_(find), result_{ViewMarkers(pattern), 0},
        attempts_(static_cast<size_t>(pattern.count()), 0), tried_with_(static_cast<size_t>(pattern.count()), 0) {}

  GrowthResult run() {
    for (int id = 0; id < p_.count(); ++id) {
      const size_t i = static_cast<size_t>(id);
      const float speed = static_cast<float>(cv::norm((*s_.motion)[i]));
      if ((*s_.measured)[i] && speed <= o_.seed_speed * (*s_.spacing)[i] && search(id, temporal(id), o_.seed_radius)) ++result_.seeds;
    }
    grow();
    // Regions no growth reached: their own temporal prediction, then grow again.
    bool any = false;
    for (int id = 0; id < p_.count(); ++id)
      if (!result_.markers.valid[static_cast<size_t>(id)] && foundNeighbours(id) == 0)
        any = search(id, temporal(id), o_.search_radius) || any;
    if (any) grow();
    return std::move(result_);
  }

 private:
  cv::Point2f temporal(int id) const {
    const size_t i = static_cast<size_t>(id);
    return (*s_.last)[i] + o_.velocity_gain * (*s_.motion)[i];
  }

  bool search(int id, cv::Point2f guess, float radius_fraction) {
    const size_t i = static_cast<size_t>(id);
    const auto c = find_(guess, radius_fraction * (*s_.spacing)[i]);
    if (!c) return false;
    bool claimed = false;  // a neighbour already on this corner: a fold, not this marker
    forNeighbours(id, [&](int nb) {
      const size_t k = static_cast<size_t>(nb);
      claimed = claimed || (result_.markers.valid[k] && (result_.markers.point[k] - *c).dot(result_.markers.point[k] - *c) < 1.0f);
    });
    if (claimed) return false;
    result_.markers.set(id, *c);
    return true;
  }

  template <typename F>
  void forNeighbours(int id, F&& f) const {
    const int r = p_.rowOf(id), c = p_.colOf(id);
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc)
        if ((dr || dc) && r + dr >= 0 && c + dc >= 0 && r + dr < p_.rows && c + dc < p_.cols) f(p_.id(r + dr, c + dc));
  }

  int foundNeighbours(int id) const {
    int n = 0;
    forNeighbours(id, [&](int nb) { n += result_.markers.valid[static_cast<size_t>(nb)] ? 1 : 0; });
    return n;
  }

  cv::Point2f fromNeighbours(int id) const {
    return *predictFromNeighbourMotion(p_, *s_.last, *s_.measured, result_.markers, id, false);
  }

  void grow() {
    for (;;) {
      std::vector<std::pair<int, int>> frontier;  // (found neighbours, id)
      for (int id = 0; id < p_.count(); ++id) {
        const size_t i = static_cast<size_t>(id);
        if (result_.markers.valid[i] || attempts_[i] >= o_.max_attempts) continue;
        const int n = foundNeighbours(id);
        if (n > tried_with_[i]) frontier.emplace_back(n, id);
      }
      if (frontier.empty()) return;
      std::stable_sort(frontier.begin(), frontier.end(), [](auto a, auto b) { return a.first > b.first; });
      for (const auto& [n_before, id] : frontier) {
        const size_t i = static_cast<size_t>(id);
        tried_with_[i] = foundNeighbours(id);
        ++attempts_[i];
        if (search(id, fromNeighbours(id), o_.search_radius)) continue;
        if (const auto own = predictFromOwnTrack(p_, *s_.last, *s_.motion, *s_.moving, result_.markers, id))
          search(id, *own, o_.search_radius);
      }
    }
  }

  const MarkerPattern& p_;
  const GrowthState& s_;
  const GrowthOptions& o_;
  const CornerFinder& find_;
  GrowthResult result_;
  std::vector<int> attempts_, tried_with_;
};

}  // namespace

std::optional<cv::Point2f> predictFromNeighbourMotion(const MarkerPattern& p, const std::vector<cv::Point2f>& last,
                                                      const std::vector<std::uint8_t>& measured, const ViewMarkers& now,
                                                      int id, bool measured_only) {
  const auto found = [&](int r, int c) {
    if (r < 0 || c < 0 || r >= p.rows || c >= p.cols) return false;
    const size_t k = static_cast<size_t>(p.id(r, c));
    return now.valid[k] && (!measured_only || measured[k]);
  };
  const auto motionOf = [&](int r, int c) {
    const size_t k = static_cast<size_t>(p.id(r, c));
    return now.point[k] - last[k];
  };
  std::array<float, 8> dx{}, dy{};
  size_t n = 0;
  const int r = p.rowOf(id), c = p.colOf(id);
  for (int dr = -1; dr <= 1; ++dr) {
    for (int dc = -1; dc <= 1; ++dc) {
      if ((!dr && !dc) || !found(r + dr, c + dc)) continue;
      cv::Point2f m = motionOf(r + dr, c + dc);
      if (found(r + 2 * dr, c + 2 * dc)) m = 2.0f * m - motionOf(r + 2 * dr, c + 2 * dc);
      dx[n] = m.x, dy[n] = m.y, ++n;
    }
  }
  if (n == 0) return std::nullopt;
  return last[static_cast<size_t>(id)] + cv::Point2f(median8(dx, n), median8(dy, n));
}

std::optional<cv::Point2f> predictFromOwnTrack(const MarkerPattern& p, const std::vector<cv::Point2f>& last,
                                               const std::vector<cv::Point2f>& motion,
                                               const std::vector<std::uint8_t>& moving, const ViewMarkers& now, int id) {
  if (!moving[static_cast<size_t>(id)]) return std::nullopt;
  std::array<float, 8> dx{}, dy{};
  size_t n = 0;
  const int r = p.rowOf(id), c = p.colOf(id);
  for (int dr = -1; dr <= 1; ++dr) {
    for (int dc = -1; dc <= 1; ++dc) {
      if ((!dr && !dc) || r + dr < 0 || c + dc < 0 || r + dr >= p.rows || c + dc >= p.cols) continue;
      const size_t k = static_cast<size_t>(p.id(r + dr, c + dc));
      if (!now.valid[k] || !moving[k]) continue;
      const cv::Point2f change = now.point[k] - last[k] - motion[k];
      dx[n] = change.x, dy[n] = change.y, ++n;
    }
  }
  if (n == 0) return std::nullopt;
  const size_t i = static_cast<size_t>(id);
  return last[i] + motion[i] + cv::Point2f(median8(dx, n), median8(dy, n));
}

GrowthResult growGrid(const MarkerPattern& pattern, const GrowthState& state, const GrowthOptions& options,
                      const CornerFinder& find) {
  return Grower(pattern, state, options, find).run();
}

}  // namespace onetip::vision
