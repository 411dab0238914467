#include "haptics/contact_field_pca.hpp"

#include <Eigen/Eigenvalues>

#include "core/error.hpp"

namespace onetip::haptics {

ContactFieldPca ContactFieldPca::fit(const TactileDataset& fields, int components) {
  const Eigen::Index n = fields.channels;
  if (fields.size() < 2 || n < 1) throw InputError("contact field PCA: needs at least two field rows");
  if (components < 1 || components > n)
    throw InputError("contact field PCA: components must be in 1.." + std::to_string(n));
  const auto rows = static_cast<Eigen::Index>(fields.size());
  const Eigen::Map<const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> f(
      fields.sensed.data(), rows, n);
  ContactFieldPca pca;
  pca.mean_ = f.cast<double>().colwise().mean().transpose();
  const Eigen::MatrixXd centred = f.cast<double>().rowwise() - pca.mean_.transpose();
  const Eigen::MatrixXd cov = (centred.transpose() * centred) / static_cast<double>(rows);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(cov);
  const Eigen::VectorXd lambda = eig.eigenvalues().reverse().cwiseMax(0.0);
  pca.basis_ = eig.eigenvectors().rowwise().reverse().leftCols(components).transpose();
  const double total = lambda.sum();
  pca.explained_ = total > 0.0 ? lambda.head(components).sum() / total : 1.0;
  return pca;
}

void ContactFieldPca::project(const double* field, double* out) const {
  const Eigen::Map<const Eigen::VectorXd> f(field, mean_.size());
  Eigen::Map<Eigen::VectorXd>(out, basis_.rows()) = basis_ * (f - mean_);
}

PcaFeatureSensor::PcaFeatureSensor(const TactileSensorModel& field_sensor, ContactFieldPca pca)
    : field_sensor_(field_sensor), pca_(std::move(pca)), field_(static_cast<size_t>(field_sensor.channels())) {
  if (field_sensor.channels() != pca_.fieldChannels())
    throw InputError("PCA feature: the sensor reports " + std::to_string(field_sensor.channels()) +
                     " channels, the PCA was fitted on " + std::to_string(pca_.fieldChannels()));
}

void PcaFeatureSensor::sense(const ContactPlane& plate, double* out) const {
  field_sensor_.sense(plate, field_.data());
  pca_.project(field_.data(), out);
}

}  // namespace onetip::haptics
