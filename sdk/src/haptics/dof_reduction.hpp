// haptics/dof_reduction.hpp — the paper's reduced reachable spaces S_*, all
// derived from one dataset collected on a regular grid (Sec. 3.1).
//
// Grid: every motor takes the angles origin + i * step (origin 30 deg). A row
// is kept for step size `step_deg` when each of its angles lies on the coarser
// grid origin + j * step_deg (within 1e-3 deg), and for the device's degrees
// of freedom when
//   1-DoF: m1 = m2 = m3            (all three motors commanded together)
//   2-DoF: m2 = m3                 (the two rear motors tied, m1 free)
//   3-DoF: no constraint.
// m1 is the front motor, m2 and m3 the rear pair (platform_kinematics.hpp).
// From a 3-deg grid of 55^3 = 166,375 rows: step 6 with 2-DoF keeps 28^2 =
// 784 rows and step 9 with 1-DoF keeps 19, as in the paper.
#pragma once

#include <array>
#include <string>

#include "haptics/tactile_dataset.hpp"

namespace onetip::haptics {

enum class DeviceDof { one = 1, two = 2, three = 3 };

DeviceDof deviceDofFromInt(int dof);  // 1, 2 or 3; InputError otherwise

struct GridSubset {
  double step_deg = 3.0;     // must be a positive multiple of the dataset's grid step
  DeviceDof dof = DeviceDof::three;
  double origin_deg = 30.0;  // the first grid angle
  void validate() const;     // throws InputError naming the bad field
};

// True when command m belongs to the subset.
bool inSubset(const std::array<double, 3>& m, const GridSubset& subset);

// The rows of `full` that belong to the subset (order kept); InputError when none do.
TactileDataset reduceDataset(const TactileDataset& full, const GridSubset& subset);

}  // namespace onetip::haptics
