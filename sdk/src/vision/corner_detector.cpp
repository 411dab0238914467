#include "vision/corner_detector.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace onetip::vision {
namespace {

constexpr float kPi = 3.14159265358979f;

// -det(H) of a smoothed copy of `grey` (Sobel second derivatives): large and
// positive at saddle points, i.e. at checkerboard corners.
cv::Mat saddleResponse(const cv::Mat& grey) {
  cv::Mat smooth, dxx, dyy, dxy;
  cv::GaussianBlur(grey, smooth, cv::Size(5, 5), 1.0);
  cv::Sobel(smooth, dxx, CV_32F, 2, 0, 3);
  cv::Sobel(smooth, dyy, CV_32F, 0, 2, 3);
  cv::Sobel(smooth, dxy, CV_32F, 1, 1, 3);
  cv::Mat response(grey.size(), CV_32F);
  for (int y = 0; y < grey.rows; ++y) {
    const float* pxx = dxx.ptr<float>(y);
    const float* pyy = dyy.ptr<float>(y);
    const float* pxy = dxy.ptr<float>(y);
    float* out = response.ptr<float>(y);
    for (int x = 0; x < grey.cols; ++x) out[x] = pxy[x] * pxy[x] - pxx[x] * pyy[x];
  }
  return response;
}

// Parabola vertex offset through (-1, a), (0, b), (1, c), in [-0.5, 0.5].
float parabolaPeak(float a, float b, float c) {
  const float curvature = a - 2 * b + c;
  return curvature < 0 ? std::clamp(0.5f * (a - c) / curvature, -0.5f, 0.5f) : 0.0f;
}

// Local maxima (5x5) of the response above threshold x its maximum, as
// positions in the response map's own pixels, refined by a parabola per axis.
std::vector<cv::Point2f> responsePeaks(const cv::Mat& response, float threshold) {
  double max_value = 0;
  cv::minMaxLoc(response, nullptr, &max_value);
  std::vector<cv::Point2f> peaks;
  if (max_value <= 0) return peaks;
  cv::Mat dilated;
  cv::dilate(response, dilated, cv::Mat::ones(5, 5, CV_8U));
  const float floor_value = threshold * static_cast<float>(max_value);
  for (int y = 1; y + 1 < response.rows; ++y) {
    const float* above = response.ptr<float>(y - 1);
    const float* row = response.ptr<float>(y);
    const float* below = response.ptr<float>(y + 1);
    const float* top = dilated.ptr<float>(y);
    for (int x = 1; x + 1 < response.cols; ++x) {
      const float v = row[x];
      if (v <= floor_value || v < top[x]) continue;
      peaks.emplace_back(static_cast<float>(x) + parabolaPeak(row[x - 1], v, row[x + 1]),
                         static_cast<float>(y) + parabolaPeak(above[x], v, below[x]));
    }
  }
  return peaks;
}

void checkImage(const cv::Mat& grey) {
  if (grey.empty()) throw InputError("corner detector: empty image");
  if (grey.type() != CV_8UC1) throw InputError("corner detector: expected an 8-bit grey image (CV_8UC1)");
}

// Candidates from a pre-filter downsampled by f are about f/2 pixels off, so
// their quick ring test uses rings scaled by max(1, f/2).
float candidateRingScale(const CornerDetectorOptions& o) { return std::max(1.0f, 0.5f * static_cast<float>(o.prefilter_downsample)); }

SubpixelOptions fineSubpixel(const CornerDetectorOptions& o) {
  SubpixelOptions s = o.subpixel;
  s.half_window = o.fine_half_window;
  s.weight_sigma = 0.0f;
  return s;
}

float mirrorAngle(float a) { return a <= 0.0f ? 0.0f : kPi - a; }

}  // namespace

void CornerDetectorOptions::validate() const {
  if (!(inner_radius_px >= 1.0f)) throw InputError("corner_detector.inner_radius_px: must be at least 1");
  if (!(outer_radius_px > inner_radius_px) || outer_radius_px > 40.0f)
    throw InputError("corner_detector.outer_radius_px: must exceed inner_radius_px and be at most 40");
  if (samples_per_ring < 8 || samples_per_ring > 64 || samples_per_ring % 4 != 0)
    throw InputError("corner_detector.samples_per_ring: must be a multiple of 4 in 8..64");
  if (prefilter_downsample != 1 && prefilter_downsample != 2 && prefilter_downsample != 4)
    throw InputError("corner_detector.prefilter_downsample: must be 1, 2 or 4");
  if (!(prefilter_threshold > 0.0f && prefilter_threshold < 1.0f))
    throw InputError("corner_detector.prefilter_threshold: must be in (0, 1)");
  if (!(min_contrast >= 0.0f)) throw InputError("corner_detector.min_contrast: must be non-negative");
  if (!(min_symmetry >= 0.0f && min_symmetry <= 1.0f)) throw InputError("corner_detector.min_symmetry: must be in 0..1");
  if (!(min_phase_agreement >= 0.0f && min_phase_agreement <= 1.0f))
    throw InputError("corner_detector.min_phase_agreement: must be in 0..1");
  if (!(min_separation_px > 0.0f)) throw InputError("corner_detector.min_separation_px: must be positive");
  if (!(fine_search_px >= 0.0f)) throw InputError("corner_detector.fine_search_px: must be non-negative");
  if (!(fine_inner_radius_px >= 1.0f)) throw InputError("corner_detector.fine_inner_radius_px: must be at least 1");
  if (!(fine_outer_radius_px > fine_inner_radius_px) || fine_outer_radius_px > 40.0f)
    throw InputError("corner_detector.fine_outer_radius_px: must exceed fine_inner_radius_px and be at most 40");
  subpixel.validate();
  fineSubpixel(*this).validate();
}

CornerDetector::CornerDetector(CornerDetectorOptions options)
    : options_((options.validate(), options)),
      stage_{RingSampler(options.inner_radius_px, options.outer_radius_px, options.samples_per_ring),
             RingSampler(options.inner_radius_px * candidateRingScale(options), options.outer_radius_px * candidateRingScale(options),
                         options.samples_per_ring),
             SubpixelRefiner(options.subpixel)},
      fine_{RingSampler(options.fine_inner_radius_px, options.fine_outer_radius_px, options.samples_per_ring),
            RingSampler(options.fine_inner_radius_px * candidateRingScale(options),
                        options.fine_outer_radius_px * candidateRingScale(options), options.samples_per_ring),
            SubpixelRefiner(fineSubpixel(options))} {}

std::optional<Corner> CornerDetector::refineAndVerify(const Stage& stage, const cv::Mat& grey, cv::Point2f start) const {
  const float margin = std::max(stage.rings.margin(), static_cast<float>(stage.refiner.options().half_window + 2));
  const auto insideBy = [&](cv::Point2f p, float m) {
    return p.x >= m && p.y >= m && p.x < grey.cols - m && p.y < grey.rows - m;
  };
  const auto inside = [&](cv::Point2f p) { return insideBy(p, margin); };
  if (!inside(start)) return std::nullopt;
  // Cheap rejection before the refinement: four sectors with some contrast
  // on the candidate ring (scaled with the pre-filter's position error).
  if (!insideBy(start, stage.candidate_rings.margin())) return std::nullopt;
  const cv::Point pixel(static_cast<int>(std::lround(start.x)), static_cast<int>(std::lround(start.y)));
  if (!stage.candidate_rings.quickFourSectors(grey, pixel, options_.min_contrast)) return std::nullopt;
  const auto refined = stage.refiner.refine(grey, start);
  if (!refined || !inside(*refined)) return std::nullopt;
  const RingTest t = stage.rings.evaluate(grey, *refined);
  if (!t.four_sectors || t.contrast < options_.min_contrast || t.symmetry < options_.min_symmetry ||
      t.phase_agreement < options_.min_phase_agreement)
    return std::nullopt;
  Corner c;
  c.pt = *refined;
  c.score = t.score;
  c.contrast = t.contrast;
  c.edge_angle[0] = t.edge_angle[0];
  c.edge_angle[1] = t.edge_angle[1];
  c.dark_bisector = t.dark_bisector;
  return c;
}

std::vector<Corner> CornerDetector::detect(const cv::Mat& grey) const {
  checkImage(grey);
  std::vector<Corner> corners;
  const int f = options_.prefilter_downsample;
  if (grey.cols < 4 * f + 8 || grey.rows < 4 * f + 8) return corners;
  cv::Mat small;
  // Crop to a multiple of f so that the block averaging is exact (an inexact
  // scale would shift the candidates by up to f pixels across the image).
  if (f > 1) cv::resize(grey(cv::Rect(0, 0, grey.cols / f * f, grey.rows / f * f)), small,
                        cv::Size(grey.cols / f, grey.rows / f), 0, 0, cv::INTER_AREA);
  else small = grey;
  const cv::Mat response = saddleResponse(small);
  const std::vector<cv::Point2f> peaks = responsePeaks(response, options_.prefilter_threshold);
  for (const cv::Point2f& p : peaks) {
    // Centre of the f x f block that the downsampled pixel averaged.
    const cv::Point2f start((p.x + 0.5f) * f - 0.5f, (p.y + 0.5f) * f - 0.5f);
    if (auto c = refineAndVerify(stage_, grey, start)) corners.push_back(*c);
  }
  // Non-maximum suppression: strongest first, drop any within the separation.
  std::sort(corners.begin(), corners.end(), [](const Corner& a, const Corner& b) { return a.score > b.score; });
  const float sep2 = options_.min_separation_px * options_.min_separation_px;
  std::vector<Corner> kept;
  kept.reserve(corners.size());
  for (const Corner& c : corners) {
    bool near = false;
    for (const Corner& k : kept) {
      const cv::Point2f d = c.pt - k.pt;
      if (d.dot(d) < sep2) { near = true; break; }
    }
    if (!near) kept.push_back(c);
  }
  return kept;
}

std::optional<Corner> CornerDetector::detectNear(const cv::Mat& grey, cv::Point2f guess, float search_radius_px) const {
  checkImage(grey);
  auto found = searchNear(stage_, grey, guess, search_radius_px);
  if (!found && options_.fine_search_px > 0)
    found = searchNear(fine_, grey, guess, std::min(search_radius_px, options_.fine_search_px));
  return found;
}

void CornerDetector::prefetchNear(const cv::Mat& grey, const std::vector<cv::Point2f>& guesses) const noexcept {
  if (grey.empty() || grey.type() != CV_8UC1) return;
  const int reach = static_cast<int>(std::ceil(std::max(options_.outer_radius_px, options_.subpixel.half_window + 1.0f))) + 1;
  for (const cv::Point2f& g : guesses) {
    if (!(std::isfinite(g.x) && std::isfinite(g.y))) continue;
    const int cx = static_cast<int>(std::clamp(g.x, 0.0f, static_cast<float>(grey.cols - 1)));
    const int cy = static_cast<int>(std::clamp(g.y, 0.0f, static_cast<float>(grey.rows - 1)));
    const int x0 = std::max(cx - reach, 0), x1 = std::min(cx + reach, grey.cols - 1);
    const int y0 = std::max(cy - reach, 0), y1 = std::min(cy + reach, grey.rows - 1);
    for (int y = y0; y <= y1; ++y) {
      const unsigned char* row = grey.ptr<unsigned char>(y);
      __builtin_prefetch(row + x0);
      __builtin_prefetch(row + x1);
    }
  }
}

std::optional<Corner> CornerDetector::searchNear(const Stage& stage, const cv::Mat& grey, cv::Point2f guess,
                                                 float search_radius_px) const {
  const float r2 = search_radius_px * search_radius_px;
  const auto within = [&](const std::optional<Corner>& c) {
    return c && (c->pt - guess).dot(c->pt - guess) <= r2;
  };
  auto direct = refineAndVerify(stage, grey, guess);
  if (within(direct)) return direct;
  // Fall back to the strongest saddle response in the search window.
  const int r = static_cast<int>(std::ceil(search_radius_px)) + 3;
  const cv::Rect window = cv::Rect(static_cast<int>(std::lround(guess.x)) - r, static_cast<int>(std::lround(guess.y)) - r,
                                   2 * r + 1, 2 * r + 1) & cv::Rect(0, 0, grey.cols, grey.rows);
  if (window.width < 8 || window.height < 8) return std::nullopt;
  const cv::Mat response = saddleResponse(grey(window));
  const std::vector<cv::Point2f> peaks = responsePeaks(response, 0.05f);
  std::optional<Corner> best;
  for (const cv::Point2f& p : peaks) {
    auto c = refineAndVerify(stage, grey, p + cv::Point2f(static_cast<float>(window.x), static_cast<float>(window.y)));
    if (within(c) && (!best || (c->pt - guess).dot(c->pt - guess) < (best->pt - guess).dot(best->pt - guess))) best = c;
  }
  return best;
}

Corner toView(const Corner& raw_corner, const ViewHalf& view) {
  if (!view.flipped) return raw_corner;
  Corner c = raw_corner;
  c.pt = view.toView(raw_corner.pt);
  c.edge_angle[0] = mirrorAngle(raw_corner.edge_angle[0]);
  c.edge_angle[1] = mirrorAngle(raw_corner.edge_angle[1]);
  c.dark_bisector = mirrorAngle(raw_corner.dark_bisector);
  return c;
}

std::vector<Corner> detectInView(const CornerDetector& detector, const ViewHalf& view) {
  std::vector<Corner> corners = detector.detect(view.raw);
  for (Corner& c : corners) c = toView(c, view);
  return corners;
}

}  // namespace onetip::vision
