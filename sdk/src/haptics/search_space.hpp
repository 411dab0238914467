// haptics/search_space.hpp — the space the kNN search runs in: standardised
// channels, rotated onto their principal axes.
//
//   x = V^T (D s - mu)      D = diag(1 / sigma_i) (channel_scaling.hpp),
//                           mu = mean of D s over the dataset,
//                           V = eigenvectors of the covariance of D s,
//                               by decreasing eigenvalue (orthonormal).
// V is orthogonal, so |x - x'| = |D s - D s'|: the paper's standardised
// Euclidean distance, and therefore the same neighbours and Eq. 7 weights
// (up to float rounding). The rotation only helps the k-d tree: data from a
// 3-DoF display lies near a 3-D manifold in R^N, and on principal axes its
// bounding boxes are tight, so queries far from it (contacts the display
// cannot reproduce) are pruned early. Constant channels (scale 0) drop out.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "haptics/channel_scaling.hpp"
#include "haptics/tactile_dataset.hpp"

namespace onetip::haptics {

class SearchSpace {
 public:
  static SearchSpace fromDataset(const TactileDataset& dataset);

  int dims() const noexcept { return static_cast<int>(mean_.size()); }
  const ChannelScaling& scaling() const noexcept { return scaling_; }
  // x = V^T (D s - mu), dims() floats; s has dims() values in sensor units.
  void apply(const double* s, float* x) const;
  void apply(const float* s, float* x) const;
  // Every dataset row mapped into the space (row-major floats).
  std::vector<float> map(const TactileDataset& dataset) const;

 private:
  ChannelScaling scaling_;
  Eigen::VectorXd mean_;
  Eigen::MatrixXd rotation_t_;  // V^T with D folded in: x = rotation_t_ * s - offset_
  Eigen::VectorXd offset_;
};

}  // namespace onetip::haptics
