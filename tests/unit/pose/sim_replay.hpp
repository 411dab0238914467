// tests/unit/pose/sim_replay.hpp — plays a simulator scenario through the
// PoseTracker and keeps the ground truth next to the estimate, frame by frame.
//
// The simulator's field-level markers are exact; the vision front end's 3-D
// error is imitated by Gaussian noise of noise_mm per axis on every marker
// (current frames and the rest field, S, mm). Default 0.0006 mm per axis
// (1.0e-3 mm 3-D RMS): what the rendered image path measures at the
// simulator's default image noise (test_pose_end_to_end.cpp prints it: per
// axis 0.0003-0.0005 in x, y and 0.0007-0.0009 in z, 3-D 0.0008-0.0010 mm).
// When drop_fraction > 0, that fraction of the markers is lost at random in
// every frame. Seeds are fixed, so runs repeat exactly.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "input/pose_tracker.hpp"
#include "sim/ground_truth.hpp"
#include "sim/scenario.hpp"

namespace onetip::poseval {

struct ReplayOptions {
  double noise_mm = 0.0006;
  double drop_fraction = 0.0;
  unsigned seed = 7;
  input::PoseTrackerOptions tracker;
};

struct ReplayFrame {
  double t = 0;
  // ground truth
  bool gt_contact = false;
  ContactState gt_state = ContactState::none;
  Input6 gt;
  Eigen::Vector3d gt_c0{0, 0, 0};      // the truth's onset centroid c0 (S, mm): gt is its motion read there
  std::vector<std::uint8_t> gt_contact_markers, gt_slip;
  std::vector<std::uint8_t> gt_followed;  // per marker: its node touches the finger the truth follows (empty: all do)
  std::vector<Eigen::Vector3d> gt_positions;  // per marker: its true position (S, mm)
  Eigen::Vector2d gt_footprint{0, 0};  // S.x, S.y centroid of the markers whose nodes touch (true positions, mm)
  bool gt_footprint_valid = false;     // some marker touches
  // estimate
  bool contact = false;
  ContactState state = ContactState::none;
  Input6 raw, composed, euler_sum;
  Input6 sd;  // the estimate's standard deviations (mm, deg)
  std::vector<std::uint8_t> region, slip, stick;  // primary region members, markers labelled slip, stick
  int regions = 0;
  bool out_of_range = false;
  pose::PoseModel model = pose::PoseModel::none;
  int n_stick = 0, n_slip = 0, region_markers = 0;
  std::vector<input::EventType> events;
};

// The scenario's marker fields with the measurement noise applied, and the
// simulator's ground truth per frame.
struct Recording {
  MarkerField rest;
  std::vector<MarkerField> frames;
  std::vector<sim::GroundTruthFrame> truth;
  double marker_depth_mm = 0;  // the scenario pad's (the tracker is given it, as the pipeline is)
};

sim::Scenario sampleScenario(const std::string& name);  // samples/scenarios/<name>.yaml
// One frame's ground truth next to the tracker's result for it.
ReplayFrame replayFrame(const sim::GroundTruthFrame& truth, const input::TrackerResult& result, int marker_count);
Recording record(const sim::Scenario& scenario, const ReplayOptions& options = {});
// Runs a recording through a PoseTracker with options.tracker and the recording's marker depth.
std::vector<ReplayFrame> track(const Recording& recording, input::PoseTrackerOptions options = {});
std::vector<ReplayFrame> replay(const sim::Scenario& scenario, const ReplayOptions& options = {});
// The pose campaign's random run `seed` (sim/random_scenario.hpp) at field level, with its noise (0.0003 mm
// per grey level of image noise), frame for frame.
std::vector<ReplayFrame> replayCampaignRun(unsigned seed);

}  // namespace onetip::poseval
