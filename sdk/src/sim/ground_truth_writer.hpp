// sim/ground_truth_writer.hpp — writes a simulated run to a folder
// (docs/reference.md, issue 2):
//   DIR/frames/000000.png ...  (unless field-only)
//   DIR/gt_pose.csv     frame,contact,state,dx,dy,dz,yaw,pitch,roll
//   DIR/gt_markers.csv  frame,id,x,y,z,contact,slip      (S, mm)
//   DIR/calib.yaml, DIR/pattern.yaml
// Everything is written into a fresh DIR.tmp.<owner>.<random> (AtomicDir,
// core/atomic_file.hpp) and renamed to DIR at the end, so a failed or
// interrupted run (an exception from on_frame unwinds) leaves no partial
// output. DIR must be absent or an empty folder: nothing the run did not create
// is ever deleted or replaced. Staging folders of killed runs are removed only
// when provably abandoned (core/staging_owner.hpp).
#pragma once

#include <functional>
#include <string>

#include "sim/simulator.hpp"

namespace onetip::sim {

struct WriteOptions {
  bool field_only = false;
  // Called after each frame with (frame index, frame count); may print progress.
  std::function<void(const GroundTruthFrame&, int)> on_frame;
  // Called after the last frame, before the folder is moved into place: an
  // exception from it (e.g. a companion output that cannot be made) leaves no folder.
  std::function<void()> before_commit;
};

// Plays the simulator to the end and writes the run; throws InputError.
void writeSimulation(Simulator& sim, const std::string& out_dir, const WriteOptions& options);

}  // namespace onetip::sim
