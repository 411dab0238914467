#include "haptics/search_space.hpp"

#include <Eigen/Eigenvalues>

namespace onetip::haptics {

SearchSpace SearchSpace::fromDataset(const TactileDataset& dataset) {
  SearchSpace space;
  space.scaling_ = ChannelScaling::fromDataset(dataset);
  const Eigen::Index n = dataset.channels;
  const Eigen::Map<const Eigen::VectorXd> scale(space.scaling_.scale.data(), n);
  space.mean_ = Eigen::VectorXd::Zero(n);
  Eigen::MatrixXd scatter = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd row(n);
  for (size_t r = 0; r < dataset.size(); ++r) {
    for (Eigen::Index c = 0; c < n; ++c) row(c) = dataset.sensedRow(r)[c] * scale(c);
    space.mean_ += row;
  }
  space.mean_ /= static_cast<double>(dataset.size());
  for (size_t r = 0; r < dataset.size(); ++r) {
    for (Eigen::Index c = 0; c < n; ++c) row(c) = dataset.sensedRow(r)[c] * scale(c) - space.mean_(c);
    scatter.selfadjointView<Eigen::Lower>().rankUpdate(row);
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(scatter.selfadjointView<Eigen::Lower>());
  const Eigen::MatrixXd v = eig.eigenvectors().rowwise().reverse();  // decreasing eigenvalue
  space.rotation_t_ = v.transpose() * scale.asDiagonal();
  space.offset_ = v.transpose() * space.mean_;
  return space;
}

namespace {
template <typename T>
void rotate(const Eigen::MatrixXd& rotation_t, const Eigen::VectorXd& offset, const T* s, float* x) {
  const Eigen::Index n = offset.size();
  for (Eigen::Index i = 0; i < n; ++i) {
    double sum = -offset(i);
    for (Eigen::Index j = 0; j < n; ++j) sum += rotation_t(i, j) * static_cast<double>(s[j]);
    x[i] = static_cast<float>(sum);
  }
}
}  // namespace

void SearchSpace::apply(const double* s, float* x) const { rotate(rotation_t_, offset_, s, x); }
void SearchSpace::apply(const float* s, float* x) const { rotate(rotation_t_, offset_, s, x); }

std::vector<float> SearchSpace::map(const TactileDataset& dataset) const {
  std::vector<float> out(dataset.sensed.size());
  const auto n = static_cast<size_t>(dataset.channels);
  for (size_t r = 0; r < dataset.size(); ++r) apply(dataset.sensedRow(r), out.data() + n * r);
  return out;
}

}  // namespace onetip::haptics
