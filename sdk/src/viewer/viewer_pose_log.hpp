// viewer/viewer_pose_log.hpp — `onetip view --pose-out FILE`: one CSV row per
// drawn frame with the 6-D input the viewer showed, so what a person (or a
// test driving the window with synthetic input) did can be checked afterwards.
//
// Columns: frame,contact,state,dx,dy,dz,yaw,pitch,roll,sd_dx,...,sd_roll — as
// pose.csv in docs/reference.md (core/pose_csv.hpp; S frame; mm and degrees;
// state none / stick / partial_slip / slip) — then, for simulated inputs, the
// simulator's ground truth for the same frame:
// gt_contact,gt_dx,gt_dy,gt_dz,gt_yaw,gt_pitch,gt_roll; then, for sim:virtual,
// the finger's commanded pose (viewer/virtual_finger.hpp): finger_x,finger_y,
// finger_depth (mm), finger_yaw,finger_pitch,finger_roll (degrees). Written through an AtomicFile: complete at commit() or absent.
#pragma once

#include <cstdint>
#include <string>

#include "core/csv_table.hpp"
#include "pipeline/frame_processor.hpp"
#include "sim/ground_truth.hpp"
#include "sim/scenario.hpp"

namespace onetip::viewer {

class ViewerPoseLog {
 public:
  ViewerPoseLog(const std::string& path, bool with_truth, bool with_finger);
  // `truth` must be given when the log has truth columns, `finger` when it has finger columns.
  void add(std::int64_t frame, const pipeline::FrameResult& result, const sim::GroundTruthFrame* truth,
           const sim::Keyframe* finger);
  void commit() { csv_.commit(); }

 private:
  bool with_truth_, with_finger_;
  CsvWriter csv_;
};

}  // namespace onetip::viewer
