#include "synthetic_board.hpp"

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <random>

namespace onetip::vision::testing {
namespace {

constexpr double kPi = 3.14159265358979323846;

double checker(const BoardLook& look, cv::Point2d uv) {
  const double half_u = 0.5 * (look.cols + 1), half_v = 0.5 * (look.rows + 1);
  const double eu = std::abs(uv.x), ev = std::abs(uv.y);
  if (eu > half_u + 1 || ev > half_v + 1) return look.background;
  if (eu > half_u || ev > half_v) return look.light;  // border
  if (look.occluder.area() > 0 && look.occluder.contains(uv)) return look.dark * 0.5;
  // Corners at integer (u, v) (odd counts) or half-integer (even counts).
  const double su = uv.x + (look.cols % 2 == 0 ? 0.5 : 0.0), sv = uv.y + (look.rows % 2 == 0 ? 0.5 : 0.0);
  const long i = static_cast<long>(std::floor(su)), j = static_cast<long>(std::floor(sv));
  return ((i + j) % 2 == 0) ? look.dark : look.light;
}

// Distance in squares from uv to the nearest grid line of the board.
double edgeDistance(const BoardLook& look, cv::Point2d uv) {
  const double su = uv.x + (look.cols % 2 == 0 ? 0.5 : 0.0), sv = uv.y + (look.rows % 2 == 0 ? 0.5 : 0.0);
  return std::min(std::abs(su - std::round(su)), std::abs(sv - std::round(sv)));
}

}  // namespace

cv::Point2d BoardWarp::toPattern(cv::Point2d pixel) const {
  const cv::Point2d p = (pixel - cv::Point2d(cx, cy)) / square_px;
  const double f = 1.0 + bulge * std::exp(-(p.dot(p)) / (2 * bulge_sigma * bulge_sigma));
  const cv::Point2d q = p * f;
  const double a = -rotation_deg * kPi / 180.0;
  const cv::Point2d r(std::cos(a) * q.x - std::sin(a) * q.y, std::sin(a) * q.x + std::cos(a) * q.y);
  return cv::Point2d(r.x + shear * r.y, r.y) + offset;
}

cv::Point2d BoardWarp::toPixel(cv::Point2d pattern) const {
  cv::Point2d x(cx + (pattern.x - offset.x) * square_px, cy + (pattern.y - offset.y) * square_px);
  for (int it = 0; it < 50; ++it) {
    const cv::Point2d r = toPattern(x) - pattern;
    const double h = 1e-4;
    const cv::Point2d dx = (toPattern(x + cv::Point2d(h, 0)) - toPattern(x - cv::Point2d(h, 0))) / (2 * h);
    const cv::Point2d dy = (toPattern(x + cv::Point2d(0, h)) - toPattern(x - cv::Point2d(0, h))) / (2 * h);
    const double det = dx.x * dy.y - dy.x * dx.y;
    const cv::Point2d step((dy.y * r.x - dy.x * r.y) / det, (-dx.y * r.x + dx.x * r.y) / det);
    x -= step;
    if (step.dot(step) < 1e-20) break;
  }
  return x;
}

cv::Mat renderBoard(const BoardWarp& warp, const BoardLook& look, cv::Size size) {
  cv::Mat img(size, CV_32F);
  const double pixel_in_squares = 2.0 / warp.square_px;  // generous footprint bound
  for (int y = 0; y < size.height; ++y) {
    float* row = img.ptr<float>(y);
    for (int x = 0; x < size.width; ++x) {
      const cv::Point2d uv = warp.toPattern({double(x), double(y)});
      const bool near_edge = edgeDistance(look, uv) < pixel_in_squares ||
                             std::abs(std::abs(uv.x) - 0.5 * (look.cols + 1)) < 2 * pixel_in_squares + 1 ||
                             std::abs(std::abs(uv.y) - 0.5 * (look.rows + 1)) < 2 * pixel_in_squares + 1 ||
                             (look.occluder.area() > 0 &&
                              (std::abs(uv.x - look.occluder.x) < pixel_in_squares ||
                               std::abs(uv.x - look.occluder.br().x) < pixel_in_squares ||
                               std::abs(uv.y - look.occluder.y) < pixel_in_squares ||
                               std::abs(uv.y - look.occluder.br().y) < pixel_in_squares));
      if (!near_edge) {
        row[x] = static_cast<float>(checker(look, uv));
        continue;
      }
      double sum = 0;
      for (int sy = 0; sy < 4; ++sy)
        for (int sx = 0; sx < 4; ++sx)
          sum += checker(look, warp.toPattern({x - 0.375 + 0.25 * sx, y - 0.375 + 0.25 * sy}));
      row[x] = static_cast<float>(sum / 16.0);
    }
  }
  if (look.blur_sigma > 0) cv::GaussianBlur(img, img, cv::Size(0, 0), look.blur_sigma);
  if (look.light_ramp != 0) {
    for (int x = 0; x < size.width; ++x)
      img.col(x) *= 1.0 - 0.5 * look.light_ramp + look.light_ramp * x / size.width;
  }
  if (look.noise_sigma > 0) {
    std::mt19937_64 rng(look.seed);
    std::normal_distribution<float> noise(0.0f, static_cast<float>(look.noise_sigma));
    for (int y = 0; y < size.height; ++y) {
      float* row = img.ptr<float>(y);
      for (int x = 0; x < size.width; ++x) row[x] += noise(rng);
    }
  }
  cv::Mat out;
  img.convertTo(out, CV_8U);  // rounds and saturates
  return out;
}

std::vector<GroundTruthCorner> groundTruthCorners(const BoardWarp& warp, const BoardLook& look, cv::Size size,
                                                  double margin_px) {
  std::vector<GroundTruthCorner> out;
  for (int r = 0; r < look.rows; ++r) {
    for (int c = 0; c < look.cols; ++c) {
      const cv::Point2d uv(c - 0.5 * (look.cols - 1), r - 0.5 * (look.rows - 1));
      const cv::Point2d px = warp.toPixel(uv);
      const bool inside = px.x >= margin_px && px.y >= margin_px && px.x < size.width - margin_px &&
                          px.y < size.height - margin_px;
      // Occluded: any of the four squares around the corner touches the band.
      const bool hidden = look.occluder.area() > 0 &&
                          (look.occluder & cv::Rect2d(uv.x - 1, uv.y - 1, 2, 2)).area() > 0;
      out.push_back({r, c, px, inside && !hidden});
    }
  }
  return out;
}

}  // namespace onetip::vision::testing
