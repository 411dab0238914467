// haptic_onetip_features: which fixed-length feature of onetip's contact
// field should the kNN renderer search in? Compares, by rendering error,
//   grid75  the 5 x 5 coarse grid of marker displacements (75 channels),
//   pcaK    the first K principal components of the full field (K = 10, 20, 40),
//           fitted on the fields of the 9-deg grid (6,859 configurations; the
//           full 3-deg field set would take 0.6 GB).
// One sweep of the 3-deg grid senses the full field (867 channels) once per
// configuration and derives every feature from it. The six remote interactions
// (25 Hz, one repetition) are rendered under all 27 conditions for each
// feature; the device is driven to the command, and what the pad feels there is
// compared with what it felt remotely on a scale common to all features: the
// full field, Eq. 9 with the full field's per-channel sigma over the 3-deg grid
// (channels that never move left out), and the mean marker displacement error
// in mm. Writes <out_dir>/onetip_features.csv.
// usage: haptic_onetip_features OUT_DIR
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <functional>
#include <map>
#include <memory>

#include "core/csv_table.hpp"
#include "haptics/contact_field_pca.hpp"
#include "haptics/display_grid.hpp"
#include "haptics/dof_reduction.hpp"
#include "haptics/knn_renderer.hpp"
#include "haptics/onetip_contact_sensor.hpp"
#include "haptics/remote_interactions.hpp"

using namespace onetip;
using namespace onetip::haptics;

namespace {

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Feature {
  std::string name;
  std::function<void(const double* field, double* out)> derive;
  int channels = 0;
  double explained = 1.0;
  TactileDataset dataset;
};

struct FieldError {
  double eq9 = 0.0, mm = 0.0;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: haptic_onetip_features OUT_DIR\n";
    return 2;
  }
  OnetipSensorOptions field_options;
  field_options.marker_stride = 1;
  const OnetipContactSensor field_sensor(field_options);
  const OnetipContactSensor grid_sensor;  // only for its marker ids
  const PlatformKinematics device;
  const auto nf = static_cast<size_t>(field_sensor.channels());

  auto t0 = std::chrono::steady_clock::now();
  const TactileDataset coarse_fields = simulateDataset(device, field_sensor, 9.0);
  std::vector<Feature> features;
  std::vector<size_t> grid_channels;
  for (int id : grid_sensor.markers())
    for (size_t c = 0; c < 3; ++c) grid_channels.push_back(3 * static_cast<size_t>(id) + c);
  features.push_back({"grid75",
                      [grid_channels](const double* f, double* out) {
                        for (size_t i = 0; i < grid_channels.size(); ++i) out[i] = f[grid_channels[i]];
                      },
                      static_cast<int>(grid_channels.size()), 1.0, {}});
  for (int k : {10, 20, 40}) {
    auto pca = std::make_shared<ContactFieldPca>(ContactFieldPca::fit(coarse_fields, k));
    features.push_back({"pca" + std::to_string(k), [pca](const double* f, double* out) { pca->project(f, out); },
                        k, pca->explainedVariance(), {}});
  }
  std::fprintf(stderr, "PCA fit on %zu fields: %.1f s\n", coarse_fields.size(), secondsSince(t0));

  // One sweep: every feature's dataset and the full field's sigma.
  t0 = std::chrono::steady_clock::now();
  std::vector<double> field(nf), sum(nf, 0.0), sum_sq(nf, 0.0);
  for (auto& f : features) f.dataset.channels = f.channels;
  const auto configurations = gridConfigurations(3.0);
  for (const auto& m : configurations) {
    field_sensor.sense(device.forward(m).plane, field.data());
    for (size_t i = 0; i < nf; ++i) {
      sum[i] += field[i];
      sum_sq[i] += field[i] * field[i];
    }
    for (auto& f : features) {
      std::vector<double> x(static_cast<size_t>(f.channels));
      f.derive(field.data(), x.data());
      f.dataset.append(m, x);
    }
  }
  std::vector<double> field_scale(nf, 0.0);
  int moving = 0;
  const double rows = static_cast<double>(configurations.size());
  for (size_t i = 0; i < nf; ++i) {
    const double var = sum_sq[i] / rows - std::pow(sum[i] / rows, 2);
    if (var > 1e-12) {
      field_scale[i] = 1.0 / std::sqrt(var);
      ++moving;
    }
  }
  std::fprintf(stderr, "3-deg sweep of %zu configurations: %.1f s\n", configurations.size(), secondsSince(t0));

  // Remote recordings: full fields.
  InteractionOptions io;
  io.rate_hz = 25.0;
  io.repetitions = 1;
  std::vector<std::vector<double>> remote;
  for (RemoteInteraction i : kRemoteInteractions)
    for (const ContactPlane& p : remoteInteraction(i, io, field_sensor.shape())) remote.push_back(field_sensor.sense(p));

  CsvWriter out(std::string(argv[1]) + "/onetip_features.csv",
                {"feature", "channels", "explained_variance", "step_deg", "neighbors", "dof", "field_eq9", "field_mm"});
  std::map<std::string, std::pair<double, double>> mean_by_feature;
  for (auto& f : features) {
    std::vector<std::vector<double>> queries;
    for (const auto& r : remote) {
      std::vector<double> x(static_cast<size_t>(f.channels));
      f.derive(r.data(), x.data());
      queries.push_back(std::move(x));
    }
    for (double step : {3.0, 6.0, 9.0})
      for (int dof : {1, 2, 3}) {
        const KnnRenderer renderer(reduceDataset(f.dataset, {step, deviceDofFromInt(dof), kServoMinDeg}));
        for (int n : {1, 4, 8}) {
          FieldError e;
          for (size_t q = 0; q < queries.size(); ++q) {
            const RenderResult r = renderer.render(queries[q].data(), n);
            field_sensor.sense(device.forward(r.command).plane, field.data());
            double eq9 = 0.0, mm = 0.0;
            for (size_t i = 0; i < nf; ++i) eq9 += std::abs(field[i] - remote[q][i]) * field_scale[i];
            for (size_t k = 0; k < nf / 3; ++k)
              mm += std::hypot(field[3 * k] - remote[q][3 * k], field[3 * k + 1] - remote[q][3 * k + 1],
                               field[3 * k + 2] - remote[q][3 * k + 2]);
            e.eq9 += eq9 / moving;
            e.mm += mm / static_cast<double>(nf / 3);
          }
          e.eq9 /= static_cast<double>(queries.size());
          e.mm /= static_cast<double>(queries.size());
          mean_by_feature[f.name].first += e.eq9 / 27.0;
          mean_by_feature[f.name].second += e.mm / 27.0;
          out.row({f.name, std::to_string(f.channels), formatNumber(f.explained, 6), formatNumber(step),
                   std::to_string(n), std::to_string(dof), formatNumber(e.eq9, 4), formatNumber(e.mm, 5)});
          if (step == 3.0 && dof == 3)
            std::printf("%-7s step 3 n %d 3-DoF: field Eq.9 %.4f, %.4f mm\n", f.name.c_str(), n, e.eq9, e.mm);
        }
      }
  }
  out.commit();
  for (const auto& f : features)
    std::printf("%-7s (%d ch, explained %.5f): mean over 27 conditions: field Eq.9 %.4f, %.4f mm\n", f.name.c_str(),
                f.channels, f.explained, mean_by_feature[f.name].first, mean_by_feature[f.name].second);
  return 0;
}
