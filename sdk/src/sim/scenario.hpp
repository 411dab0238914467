// sim/scenario.hpp — a simulator scenario: a small YAML keyframe file
// (samples/scenarios/*.yaml, plain YAML or JSON).
//
// A touch scenario moves one or more indenters through keyframes:
//   indenters:
//     - shape: ellipsoid | sphere | plate
//       semi_axes: [7, 9, 6]          # ellipsoid; sphere: radius: 6; plate: size: [w, l]
//       pivot: [0, 0, 0]              # rotation centre, indenter frame (default: its tip)
//       keyframes:
//         - {t: 0.0, x: 0, y: 0, depth: -0.5, yaw: 0, pitch: 0, roll: 0}
//         - {t: 1.0, depth: 3.5}      # omitted fields keep the previous value
// Pose at time t (linear interpolation between keyframes, angles in degrees):
//   R = Rz(yaw) Ry(roll) Rx(pitch); the pivot sits at (x, y, z) in S with z
//   chosen so that the posed body's lowest point is `depth` mm below the
//   undeformed outer surface (negative depth: above it, no contact).
// A calibration scenario (kind: calibration) instead shows a rigid
// checkerboard target at `poses` random poses (see CalibrationTarget).
// Optional sections: pad (PadOptions), camera (CameraRigOptions), image
// (ImageEffects), fps (default 30), seed, and the world effects, each off
// when absent (sim/world_effects.hpp): viscoelastic {relaxation, time_s},
// drift {expansion, offset_mm, time_s}, camera_shift {px, at_s, ramp_s,
// view}, damage {ids, fraction, seed, radius}, light {flicker,
// exposure_step, step_at_s}.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "sim/camera_rig.hpp"
#include "sim/indenter.hpp"
#include "sim/pad.hpp"
#include "sim/renderer.hpp"
#include "sim/world_effects.hpp"

namespace onetip::sim {

struct Keyframe {
  double t = 0;
  double x = 0, y = 0, depth = -1.0;       // mm
  double yaw = 0, pitch = 0, roll = 0;     // degrees
};

struct IndenterTrack {
  IndenterGeometry geometry;
  Eigen::Vector3d pivot{0, 0, 0};
  std::vector<Keyframe> keyframes;  // strictly increasing t
  Keyframe at(double t) const;      // clamped to the first/last keyframe
};

struct CalibrationTarget {
  int rows = 8, cols = 11;          // inner corners
  double square_mm = 2.0;
  int poses = 24;
  double tilt_deg = 30, yaw_deg = 20, shift_mm = 3, depth_min_mm = -2, depth_max_mm = 3;
};

struct Scenario {
  std::string name;
  std::string description;
  std::string kind = "touch";       // touch | calibration
  double fps = 30;
  unsigned seed = 1;
  PadOptions pad;
  CameraRigOptions camera;
  ImageEffects image;
  WorldEffects world;
  std::vector<IndenterTrack> indenters;
  CalibrationTarget target;

  bool isCalibration() const { return kind == "calibration"; }
  double duration() const;          // seconds (last keyframe time)
  int defaultFrameCount() const;    // duration * fps + 1, or target.poses
  // Indenter poses in the pad frame P at time t.
  std::vector<Eigen::Isometry3d> posesAt(double t, const PadLattice& lattice) const;
};

// A scenario may last at most this many frames (duration x fps + 1): 2.3 h
// at 30 fps, 14 min at 240 fps.
constexpr int kMaxScenarioFrames = 250000;

// Reads and validates a scenario (YAML or JSON, core/config_file.hpp); throws
// InputError "<file>:<line>: key '<key>': what is wrong".
Scenario loadScenario(const std::string& path);

}  // namespace onetip::sim
