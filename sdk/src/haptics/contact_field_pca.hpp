// haptics/contact_field_pca.hpp — principal components of onetip's contact
// field, the alternative fixed-length feature to the coarse marker grid
// (onetip_contact_sensor.hpp).
//
// Fit on F field vectors f (N = 3 x markers displacements, mm) collected with
// the sensor inside the display:
//   mu = mean f,  C = 1/F sum (f - mu)(f - mu)^T,  C = V diag(lambda) V^T
// (lambda decreasing). The feature keeps the first k components:
//   x_j = v_j . (f - mu),  j = 1..k   (mm; x_1 has the largest variance).
// explainedVariance(k) = sum_{j<=k} lambda_j / sum_j lambda_j.
// PcaFeatureSensor wraps a full-field sensor and reports x (k channels).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "haptics/tactile_dataset.hpp"
#include "haptics/tactile_sensor_model.hpp"

namespace onetip::haptics {

class ContactFieldPca {
 public:
  // fields: the sensed rows of a dataset of full fields; 1 <= components <= channels.
  static ContactFieldPca fit(const TactileDataset& fields, int components);

  int components() const noexcept { return static_cast<int>(basis_.rows()); }
  int fieldChannels() const noexcept { return static_cast<int>(mean_.size()); }
  double explainedVariance() const noexcept { return explained_; }
  void project(const double* field, double* out) const;

 private:
  Eigen::VectorXd mean_;
  Eigen::MatrixXd basis_;  // k x N, rows v_j^T
  double explained_ = 0.0;
};

class PcaFeatureSensor final : public TactileSensorModel {
 public:
  // `field_sensor` must outlive this object and report pca.fieldChannels() channels.
  PcaFeatureSensor(const TactileSensorModel& field_sensor, ContactFieldPca pca);

  int channels() const override { return pca_.components(); }
  void sense(const ContactPlane& plate, double* out) const override;
  using TactileSensorModel::sense;
  double fullScale(int) const override { return 0.0; }
  FingertipShape shape() const override { return field_sensor_.shape(); }

 private:
  const TactileSensorModel& field_sensor_;
  ContactFieldPca pca_;
  mutable std::vector<double> field_;
};

}  // namespace onetip::haptics
