#include "haptics/vibration_table.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <random>

#include "core/csv_table.hpp"
#include "core/error.hpp"
#include "haptics/display_grid.hpp"
#include "haptics/vibration_plant.hpp"

namespace onetip::haptics {

void VibrationTableOptions::validate() const {
  gridAngles(step_deg);  // throws "step: ... is not in (0, 165]"
  sweep.validate();
  identification.validate();
  if (std::isnan(recording_snr_db)) throw InputError("VibrationTableOptions.recording_snr_db: must be a number");
}

SweepRecorder simulatedSweepRecorder(const PlatformKinematics& device) {
  return [&device](const std::array<double, 3>& m, const std::vector<double>& u) {
    return filterSignal(vibrationPlant(device.forward(m)), u);
  };
}

std::vector<double> withRecordingNoise(std::vector<double> y, double snr_db, std::uint64_t seed) {
  double power = 0.0;
  for (double v : y) power += v * v / static_cast<double>(y.size());
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, std::sqrt(power / std::pow(10.0, snr_db / 10.0)));
  for (double& v : y) v += noise(rng);
  return y;
}

namespace {

std::string shortest(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::vector<std::string> tableHeader() {
  std::vector<std::string> h = {"step_deg", "m1", "m2", "m3"};
  for (int i = 0; i <= kVibrationOrder; ++i) h.push_back("b" + std::to_string(i));
  for (int i = 0; i <= kVibrationOrder; ++i) h.push_back("a" + std::to_string(i));
  return h;
}
}  // namespace

VibrationTable VibrationTable::identify(const SweepRecorder& record, const VibrationTableOptions& options,
                                        const std::function<void(size_t, size_t)>& progress) {
  options.validate();
  VibrationTable table;
  table.step_deg_ = options.step_deg;
  table.per_motor_ = static_cast<int>(gridAngles(options.step_deg).size());
  const auto configurations = gridConfigurations(options.step_deg);
  const auto u = sweptSine(options.sweep);
  for (const auto& m : configurations) {
    std::vector<double> y = record(m, u);
    if (y.size() != u.size()) throw InputError("vibration table: the recorder returned a record of another length");
    if (std::isfinite(options.recording_snr_db))
      y = withRecordingNoise(std::move(y), options.recording_snr_db, options.seed + table.entries_.size());
    table.entries_.push_back(identifyTransferFunction(u, y, options.identification).tf);
    if (progress) progress(table.entries_.size(), configurations.size());
  }
  return table;
}

size_t VibrationTable::index(const std::array<double, 3>& m) const noexcept {
  size_t c = 0;
  for (double angle : m) {
    const double k = std::round((angle - kServoMinDeg) / step_deg_);
    const auto i = static_cast<size_t>(std::clamp(std::isfinite(k) ? k : 0.0, 0.0, per_motor_ - 1.0));
    c = c * static_cast<size_t>(per_motor_) + i;
  }
  return c;
}

const TransferFunction& VibrationTable::lookup(const std::array<double, 3>& m) const noexcept {
  return entries_[index(m)];
}

std::array<double, 3> VibrationTable::configuration(size_t i) const {
  const auto n = static_cast<size_t>(per_motor_);
  return {kServoMinDeg + step_deg_ * static_cast<double>(i / (n * n)),
          kServoMinDeg + step_deg_ * static_cast<double>(i / n % n),
          kServoMinDeg + step_deg_ * static_cast<double>(i % n)};
}

void VibrationTable::save(const std::string& path) const {
  CsvWriter out(path, tableHeader());
  for (size_t i = 0; i < entries_.size(); ++i) {
    const auto m = configuration(i);
    std::vector<std::string> row = {shortest(step_deg_), shortest(m[0]), shortest(m[1]), shortest(m[2])};
    for (double v : entries_[i].b) row.push_back(shortest(v));
    for (double v : entries_[i].a) row.push_back(shortest(v));
    out.row(row);
  }
  out.commit();
}

VibrationTable VibrationTable::load(const std::string& path) {
  const CsvTable t = readCsv(path);
  if (t.header != tableHeader()) throw InputError(path + ": header is not step_deg,m1,m2,m3,b0..b6,a0..a6");
  if (t.rows.empty()) throw InputError(path + ": no table rows");
  VibrationTable table;
  table.step_deg_ = parseNumber(t.rows[0][0], path + ": line 2, step_deg");
  gridAngles(table.step_deg_);
  table.per_motor_ = static_cast<int>(gridAngles(table.step_deg_).size());
  const auto grid = gridConfigurations(table.step_deg_);
  if (t.rows.size() != grid.size())
    throw InputError(path + ": has " + std::to_string(t.rows.size()) + " rows, a " + shortest(table.step_deg_) +
                     "-deg table has " + std::to_string(grid.size()));
  for (size_t r = 0; r < t.rows.size(); ++r) {
    const std::string where = path + ": line " + std::to_string(r + 2);
    std::vector<double> v;
    for (size_t c = 0; c < t.header.size(); ++c) v.push_back(parseNumber(t.rows[r][c], where + ", " + t.header[c]));
    if (v[0] != table.step_deg_ || std::abs(v[1] - grid[r][0]) > 1e-9 || std::abs(v[2] - grid[r][1]) > 1e-9 ||
        std::abs(v[3] - grid[r][2]) > 1e-9)
      throw InputError(where + ": not configuration " + std::to_string(r) + " of the grid");
    TransferFunction tf;
    std::copy_n(v.begin() + 4, kVibrationOrder + 1, tf.b.begin());
    std::copy_n(v.begin() + 5 + kVibrationOrder, kVibrationOrder + 1, tf.a.begin());
    if (tf.a[0] != 1.0 || !tf.stable()) throw InputError(where + ": not a stable filter with a0 = 1");
    table.entries_.push_back(tf);
  }
  return table;
}

}  // namespace onetip::haptics
