// calib/haptic_collection.hpp — recording the renderer's dataset with the
// tactile sensor inside the display (journal paper Sec. 2.2): the program
// behind `onetip collect`.
//
// The motor configurations of gridConfigurations(step) (display_grid.hpp:
// 30 + i step deg per motor, m1 slowest, m3 fastest) are visited in order; at
// each the rig moves the platform and reads the sensor's N channels. Rows
// (m1, m2, m3 in degrees, s1..sN in sensor units) are stored as float.
//
// Interruption and resumption. Every row is appended to the progress file
// (default "<out>.progress") as soon as it is read:
//   line 1:  "# onetip collect v1 step=<step> channels=<N> configurations=<C>"
//   line 2:  the dataset CSV header m1,m2,m3,s1,...,sN
//   then one CSV line per configuration, in grid order, floats printed in
//   their shortest round-trip form (so re-reading gives the same floats).
// Rows are flushed to the file in batches (and when stopping), never rewritten.
// A run that finds a progress file checks its first two lines against its own
// step and channels (InputError when they differ), drops a last line without
// its newline (a write cut short), checks every kept row's commands against the
// grid, and continues at the next configuration: rows are neither lost nor
// repeated. A stop request (SIGINT in `onetip collect`) or the row limit ends
// the run after the current row with status `interrupted`; nothing but the
// progress file is written. When every configuration is done, the dataset is
// written atomically (CSV, or the binary format when out ends in ".bin";
// dataset_binary.hpp) and the progress file removed.
// With a deterministic sensor (the noise-free simulations) an interrupted and
// resumed collection is identical to an uninterrupted one.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <functional>
#include <string>

#include "haptics/platform_kinematics.hpp"
#include "haptics/tactile_sensor_model.hpp"

namespace onetip::calib {

// What a collection drives: the display with the sensor inside it.
class CollectionRig {
 public:
  virtual ~CollectionRig() = default;
  virtual int channels() const = 0;
  // Moves to servo angles m (degrees) and reads channels() values into out.
  virtual void measure(const std::array<double, 3>& m, double* out) = 0;
};

// The simulated display (platform_kinematics.hpp) with a simulated sensor.
class SimulatedRig final : public CollectionRig {
 public:
  SimulatedRig(const haptics::PlatformKinematics& device, const haptics::TactileSensorModel& sensor)
      : device_(device), sensor_(sensor) {}
  int channels() const override { return sensor_.channels(); }
  void measure(const std::array<double, 3>& m, double* out) override;

 private:
  const haptics::PlatformKinematics& device_;
  const haptics::TactileSensorModel& sensor_;
};

struct CollectionOptions {
  double step_deg = 3.0;       // grid step, (0, 165]
  std::string out_path;        // dataset: .csv, or .bin for the binary format
  std::string progress_path;   // empty: out_path + ".progress"
  long max_new_rows = -1;      // stop after this many new rows (-1: no limit)
  int flush_every_rows = 64;   // progress file flush batch, >= 1
  void validate() const;       // throws InputError naming the bad field
  std::string progressPath() const { return progress_path.empty() ? out_path + ".progress" : progress_path; }
};

struct CollectionProgress {
  size_t done = 0;             // rows in the progress file
  size_t total = 0;            // configurations
  size_t resumed = 0;          // rows found at start
  double elapsed_s = 0.0;      // this run
};

struct CollectionResult {
  enum class Status { complete, interrupted };
  Status status = Status::complete;
  size_t rows = 0;             // rows in the progress file / dataset
  size_t total = 0;
  size_t resumed = 0;          // rows taken over from an earlier run
  size_t new_rows = 0;
};

// Runs or resumes a collection. `stop` (optional) is polled after every row;
// `progress` (optional) is called after every row.
CollectionResult collectDataset(CollectionRig& rig, const CollectionOptions& options,
                                const std::atomic<bool>* stop = nullptr,
                                const std::function<void(const CollectionProgress&)>& progress = {});

// "[#####.....]  45.2%  75,123/166,375 rows  1,234 rows/s  ETA 1m14s"
std::string formatProgressBar(const CollectionProgress& p, int width = 30);

}  // namespace onetip::calib
