#include "haptics/objective_evaluation.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "core/error.hpp"
#include "haptics/channel_scaling.hpp"
#include "haptics/knn_renderer.hpp"

namespace onetip::haptics {

void ObjectiveEvaluationOptions::validate() const {
  if (steps_deg.empty() || neighbors.empty() || dofs.empty())
    throw InputError("ObjectiveEvaluationOptions: steps_deg, neighbors and dofs must not be empty");
  for (double s : steps_deg)
    if (!(s > 0.0)) throw InputError("ObjectiveEvaluationOptions.steps_deg: must be positive");
  for (int n : neighbors)
    if (n < 1) throw InputError("ObjectiveEvaluationOptions.neighbors: must be >= 1");
  for (int d : dofs) deviceDofFromInt(d);
  interactions.validate();
  if (servo) servo->validate();
}

namespace {

// fullScale(i) of the sensor, or channel i's range over the dataset when the
// sensor declares none.
std::vector<double> channelFullScale(const TactileDataset& full, const TactileSensorModel& sensor) {
  const auto nc = static_cast<size_t>(full.channels);
  std::vector<double> lo(nc, 1e300), hi(nc, -1e300), out(nc);
  for (size_t r = 0; r < full.size(); ++r)
    for (size_t i = 0; i < nc; ++i) {
      lo[i] = std::min(lo[i], static_cast<double>(full.sensedRow(r)[i]));
      hi[i] = std::max(hi[i], static_cast<double>(full.sensedRow(r)[i]));
    }
  for (size_t i = 0; i < nc; ++i) {
    const double declared = sensor.fullScale(static_cast<int>(i));
    out[i] = declared > 0.0 ? declared : hi[i] - lo[i];
  }
  return out;
}

struct Recording {
  RemoteInteraction interaction;
  std::vector<double> sensed;  // K x N
};

}  // namespace

std::vector<EvaluationRow> runObjectiveEvaluation(const TactileDataset& full, const TactileSensorModel& remote,
                                                  const TactileSensorModel& in_device,
                                                  const PlatformKinematics& device,
                                                  const ObjectiveEvaluationOptions& options,
                                                  const std::function<void(int, int)>& progress) {
  options.validate();
  const int n_channels = full.channels;
  if (remote.channels() != n_channels || in_device.channels() != n_channels)
    throw InputError("objective evaluation: the sensors' channel counts differ from the dataset's");
  const auto nc = static_cast<size_t>(n_channels);
  const ChannelScaling scaling = ChannelScaling::fromDataset(full);
  const int counted = n_channels - scaling.constantChannels();
  if (counted == 0) throw InputError("objective evaluation: every dataset channel is constant");
  const std::vector<double> full_scale = channelFullScale(full, in_device);

  std::vector<Recording> recordings;
  for (RemoteInteraction interaction : kRemoteInteractions) {
    Recording rec{interaction, {}};
    for (const ContactPlane& p : remoteInteraction(interaction, options.interactions, remote.shape())) {
      const auto s = remote.sense(p);
      rec.sensed.insert(rec.sensed.end(), s.begin(), s.end());
    }
    recordings.push_back(std::move(rec));
  }

  std::vector<EvaluationRow> rows;
  const int total = static_cast<int>(options.steps_deg.size() * options.dofs.size() * options.neighbors.size());
  int done = 0;
  std::vector<double> felt(nc);
  for (double step : options.steps_deg)
    for (int dof : options.dofs) {
      const GridSubset subset{step, deviceDofFromInt(dof), kServoMinDeg};
      const TactileDataset reduced = reduceDataset(full, subset);
      const KnnRenderer renderer(reduced);
      for (int n : options.neighbors) {
        for (const Recording& rec : recordings) {
          EvaluationRow row;
          row.interaction = rec.interaction;
          row.condition = {step, n, subset.dof};
          row.dataset_rows = reduced.size();
          const size_t samples = rec.sensed.size() / nc;
          double sum_norm = 0.0, sum_full = 0.0;
          std::optional<ServoResponse> servos;
          if (options.servo) servos.emplace(*options.servo);
          for (size_t k = 0; k < samples; ++k) {
            const double* s = rec.sensed.data() + k * nc;
            const RenderResult r = renderer.render(s, n);
            const std::array<double, 3> angles =
                servos ? servos->advance(r.command, 1.0 / options.interactions.rate_hz) : r.command;
            in_device.sense(device.forward(angles).plane, felt.data());
            sum_norm += scaling.meanStandardizedError(s, felt.data());
            for (size_t i = 0; i < nc; ++i)
              if (scaling.scale[i] > 0.0) sum_full += std::abs(s[i] - felt[i]) / full_scale[i];
          }
          row.normalized_error = sum_norm / static_cast<double>(samples);
          row.percent_full_scale = 100.0 * sum_full / (static_cast<double>(samples) * counted);
          rows.push_back(row);
        }
        if (progress) progress(++done, total);
      }
    }
  std::stable_sort(rows.begin(), rows.end(), [](const EvaluationRow& a, const EvaluationRow& b) {
    return std::make_tuple(static_cast<int>(a.interaction), a.condition.step_deg, a.condition.neighbors,
                           static_cast<int>(a.condition.dof)) <
           std::make_tuple(static_cast<int>(b.interaction), b.condition.step_deg, b.condition.neighbors,
                           static_cast<int>(b.condition.dof));
  });
  return rows;
}

std::vector<ConditionSummary> summarizeByCondition(const std::vector<EvaluationRow>& rows) {
  std::map<std::tuple<double, int, int>, std::vector<const EvaluationRow*>> groups;
  for (const auto& r : rows)
    groups[{r.condition.step_deg, r.condition.neighbors, static_cast<int>(r.condition.dof)}].push_back(&r);
  std::vector<ConditionSummary> out;
  for (const auto& [key, members] : groups) {
    ConditionSummary s;
    s.condition = members.front()->condition;
    const double count = static_cast<double>(members.size());
    for (const auto* m : members) {
      s.mean_normalized_error += m->normalized_error / count;
      s.mean_percent_full_scale += m->percent_full_scale / count;
    }
    double var = 0.0;
    for (const auto* m : members) var += std::pow(m->normalized_error - s.mean_normalized_error, 2);
    s.sem_normalized_error = count > 1 ? std::sqrt(var / (count - 1)) / std::sqrt(count) : 0.0;
    out.push_back(s);
  }
  return out;
}

}  // namespace onetip::haptics
