// haptics/vibration_table.hpp — the vibration channel's lookup table from
// display configuration to fitted transfer function (da Vinci paper,
// Algorithm 1: c_* of the configuration the renderer selected).
//
// Built offline on the motor grid of step theta (display_grid.hpp: angles
// 30 + i theta deg, i = 0..I-1, configuration c = (i1 I + i2) I + i3): for each
// configuration the swept sine u (tf_identification.hpp) is played through the
// vibration path at that platform pose and the AC channel's record y = H u
// (+ white noise at `recording_snr_db`, when finite) is fitted with a
// 6-pole/6-zero model. In the simulation H is vibration_plant.hpp's ground
// truth; on hardware a recorder callback plays and records the sweep.
// Lookup (render loop, O(1), no allocation): each commanded angle is clamped to
// [30, 30 + (I-1) theta] and rounded to the nearest grid angle, i.e. the table
// entry nearest to m in every motor.
// File (CSV): header step_deg,m1,m2,m3,b0..b6,a0..a6, one row per
// configuration in grid order; numbers in shortest round-trip form.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "haptics/platform_kinematics.hpp"
#include "haptics/tf_identification.hpp"

namespace onetip::haptics {

struct VibrationTableOptions {
  double step_deg = 15.0;  // table grid step (11^3 = 1,331 configurations)
  SweepOptions sweep;
  IdentificationOptions identification;
  double recording_snr_db = std::numeric_limits<double>::infinity();  // inf: clean records
  std::uint64_t seed = 1;  // recording noise of entry i: seed + i
  void validate() const;   // throws InputError naming the bad field
};

// Plays `sweep` through the vibration path at the given servo angles and
// returns what the AC channel records (same length).
using SweepRecorder = std::function<std::vector<double>(const std::array<double, 3>&, const std::vector<double>&)>;

// y plus white Gaussian noise of power mean(y^2) / 10^(snr_db / 10).
std::vector<double> withRecordingNoise(std::vector<double> y, double snr_db, std::uint64_t seed);

// The simulated recorder: the plant of vibration_plant.hpp at device.forward(m).
SweepRecorder simulatedSweepRecorder(const PlatformKinematics& device);

class VibrationTable {
 public:
  // Identifies every configuration of the grid; `progress(done, total)` optional.
  static VibrationTable identify(const SweepRecorder& record, const VibrationTableOptions& options = {},
                                 const std::function<void(size_t, size_t)>& progress = {});
  static VibrationTable load(const std::string& path);  // InputError naming file and line
  void save(const std::string& path) const;             // atomic

  const TransferFunction& lookup(const std::array<double, 3>& m) const noexcept;
  size_t index(const std::array<double, 3>& m) const noexcept;  // entry used by lookup(m)
  const TransferFunction& entry(size_t i) const { return entries_.at(i); }
  std::array<double, 3> configuration(size_t i) const;
  size_t size() const noexcept { return entries_.size(); }
  double stepDeg() const noexcept { return step_deg_; }

 private:
  double step_deg_ = 15.0;
  int per_motor_ = 0;
  std::vector<TransferFunction> entries_;
};

}  // namespace onetip::haptics
