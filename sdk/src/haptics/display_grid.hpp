// haptics/display_grid.hpp — the motor configurations a collection visits and
// the in-memory dataset of a simulated sensor inside the simulated device.
//
// Grid of step theta: every motor takes 30 + i * theta deg for i = 0..I-1 with
// 30 + (I-1) * theta < 195 (the paper's (195 - 30) / theta values per motor:
// 55 for 3 deg, so 55^3 = 166,375 configurations). Order: m1 slowest, m3
// fastest; configuration c = (i1 * I + i2) * I + i3. Collection resumes by
// this index.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "haptics/platform_kinematics.hpp"
#include "haptics/tactile_dataset.hpp"
#include "haptics/tactile_sensor_model.hpp"

namespace onetip::haptics {

// The most configurations a grid may have: 100^3 (about 92 MB as a 20-channel
// dataset in memory, hours of collection); smaller steps are refused before any
// allocation (`collect --step 1e-9` once grew to 8.4 GB).
constexpr std::size_t kMaxGridConfigurations = 1'000'000;
constexpr double kMinGridStepDeg = 1.65;  // 165 / 100: the smallest step within the bound

// Angles per motor on the grid (InputError unless 0 < step_deg <= 165 and the
// grid has at most kMaxGridConfigurations configurations).
std::vector<double> gridAngles(double step_deg);
// All configurations in collection order.
std::vector<std::array<double, 3>> gridConfigurations(double step_deg);

// The dataset of `sensor` inside the device at every grid configuration
// (what `onetip collect` records, without files or progress).
TactileDataset simulateDataset(const PlatformKinematics& device, const TactileSensorModel& sensor,
                               double step_deg);

}  // namespace onetip::haptics
