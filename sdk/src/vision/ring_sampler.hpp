// vision/ring_sampler.hpp — the double-layer circular sampler.
//
// Around a centre c, N samples (bilinear) on each of two concentric rings,
// s_k = I(c + r (cos a_k, sin a_k)), a_k = 2 pi k / N (image axes: x right,
// y down). At a checkerboard corner each ring crosses four sectors that
// alternate dark/light; under any locally affine map (scale, shear, rotation)
// opposite sectors keep the same colour, so the ring is centrally symmetric,
// s_k ~ s_{k+N/2}; and since the sector boundaries are straight lines through
// c, both rings show the same sign pattern at the same angles (in phase).
// Per ring: mean m, contrast C = mean |s_k - m|, labels +-1 where
// |s_k - m| > C/4 (0 in between), exactly four label changes around the ring;
// symmetry = 1 - mean |s_k - s_{k+N/2}| / (2 C); phase agreement = fraction
// of angles with non-zero labels on both rings where they agree.
// score = min contrast x min symmetry x agreement (grey levels).
// quickFourSectors applies the outer ring's four-sector test alone, on whole
// pixels, to reject pre-filter candidates cheaply.
// The four sign crossings on the outer ring give the two edge lines and the
// bisector of the dark sectors (radians, modulo pi).
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace onetip::vision {

struct RingTest {
  bool four_sectors = false;  // both rings show exactly four alternating sectors
  float contrast = 0.0f;      // grey levels, the smaller of the two rings
  float symmetry = 0.0f;      // 0..1
  float phase_agreement = 0.0f;  // 0..1
  float score = 0.0f;
  float edge_angle[2] = {0, 0};
  float dark_bisector = 0.0f;
};

class RingSampler {
 public:
  // Radii in pixels (inner < outer), samples per ring a multiple of 4.
  RingSampler(float inner_radius, float outer_radius, int samples);
  // The centre must lie at least margin() pixels inside the image.
  RingTest evaluate(const cv::Mat& grey, cv::Point2f centre) const;
  // Cheap pre-test at a whole pixel: the outer ring, sampled at the nearest
  // pixels, shows four sectors with a contrast of at least min_contrast.
  bool quickFourSectors(const cv::Mat& grey, cv::Point centre, float min_contrast) const;
  float margin() const noexcept { return outer_radius_ + 2.0f; }

 private:
  float outer_radius_;
  int samples_;
  std::vector<cv::Point2f> inner_offset_, outer_offset_;
  std::vector<cv::Point> outer_pixel_;  // outer_offset_ rounded
};

}  // namespace onetip::vision
