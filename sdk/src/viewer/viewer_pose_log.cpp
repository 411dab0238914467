#include "viewer/viewer_pose_log.hpp"

#include <stdexcept>
#include <vector>

#include "core/pose_csv.hpp"

namespace onetip::viewer {

namespace {
std::vector<std::string> header(bool with_truth, bool with_finger) {
  std::vector<std::string> h = poseCsvHeader(true);
  if (with_truth) h.insert(h.end(), {"gt_contact", "gt_dx", "gt_dy", "gt_dz", "gt_yaw", "gt_pitch", "gt_roll"});
  if (with_finger)
    h.insert(h.end(), {"finger_x", "finger_y", "finger_depth", "finger_yaw", "finger_pitch", "finger_roll"});
  return h;
}

void appendNumbers(std::vector<std::string>& row, std::initializer_list<double> values) {
  for (double v : values) row.push_back(formatNumber(v));
}
}  // namespace

ViewerPoseLog::ViewerPoseLog(const std::string& path, bool with_truth, bool with_finger)
    : with_truth_(with_truth), with_finger_(with_finger), csv_(path, header(with_truth, with_finger)) {}

void ViewerPoseLog::add(std::int64_t frame, const pipeline::FrameResult& result, const sim::GroundTruthFrame* truth,
                        const sim::Keyframe* finger) {
  if ((with_truth_ && !truth) || (with_finger_ && !finger))
    throw std::logic_error("ViewerPoseLog::add: the ground truth or finger pose is missing");
  const input::TrackerResult& p = result.pose;
  std::vector<std::string> row = poseCsvRow(frame, p.contact, p.state, p.raw, p.sd);
  if (with_truth_) {
    row.push_back(truth->in_contact ? "1" : "0");
    const Input6& g = truth->input;
    appendNumbers(row, {g.dx, g.dy, g.dz, g.yaw, g.pitch, g.roll});
  }
  if (with_finger_) appendNumbers(row, {finger->x, finger->y, finger->depth, finger->yaw, finger->pitch, finger->roll});
  csv_.row(row);
}

}  // namespace onetip::viewer
