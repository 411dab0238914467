// pipeline/frame_processor.hpp — one camera frame in, markers, contact and the
// 6-D input out: the SDK's deterministic, single-threaded core.
//
//   frame (grey, both views) -> split (ROIs, no copy) -> detect corners per view
//   -> track ids per view -> a moved mirror or camera corrected (after frames
//   out of contact, vision/view_shift.hpp) -> triangulate ids seen in both
//   (points undistorted, not images) -> S from the rest markers -> contact,
//   stick/slip, pose, events
//
// The first frame given to setReference() (or process() before any reference)
// is the rest state: it assigns the marker ids (anchored in each view,
// docs/reference.md) and defines the sensor frame S. Every stage is timed
// (milliseconds, steady clock, on the calling thread). Bad frames (wrong size,
// empty, tracking lost) give a status and a message, never an exception, so a
// stream goes on with its next good frame. Threads, queues and time-stamping
// live in Pipeline, not here.
#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <string>

#include "core/calibration.hpp"
#include "core/marker_field.hpp"
#include "core/pattern.hpp"
#include "core/sensor_frame.hpp"
#include "input/pose_tracker.hpp"
#include "vision/corner_detector.hpp"
#include "vision/grid_tracker.hpp"
#include "vision/triangulator.hpp"
#include "vision/view_shift.hpp"

namespace onetip::pipeline {

struct FrameProcessorOptions {
  vision::CornerDetectorOptions detector;
  vision::GridTrackerOptions tracker;
  vision::TriangulatorOptions triangulator;
  vision::ViewShiftOptions view_shift;  // a mirror or the camera moved: corrected before triangulation
  input::PoseTrackerOptions pose;  // its marker_depth_mm is the pattern's (set by the constructor)
  int min_markers = 12;  // fewer triangulated markers: the frame is "lost" (no pose update)
  void validate() const;  // throws InputError naming the bad field
};

enum class FrameStatus : std::uint8_t {
  ok,         // processed
  reference,  // this frame became the rest state
  skipped,    // unusable frame (wrong size, empty, not grey): message says why
  lost,       // too few markers found or tracked: message says why
};
const char* toString(FrameStatus s) noexcept;

// Milliseconds per stage for one frame; process = everything after decode.
struct StageTimes {
  double detect = 0, track = 0, triangulate = 0, contact = 0, pose = 0, process = 0;
};

struct FrameResult {
  FrameStatus status = FrameStatus::skipped;
  std::string message;
  double t = 0;
  MarkerField markers;  // S, mm (valid where triangulated)
  int found_left = 0, found_right = 0;
  input::TrackerResult pose;  // contact, state, Input6, events (default when not ok)
  StageTimes times;
};

class FrameProcessor {
 public:
  // Throws InputError for an invalid calibration, pattern or options.
  FrameProcessor(const StereoCalibration& calib, const MarkerPattern& pattern, FrameProcessorOptions options = {});
  ~FrameProcessor();
  FrameProcessor(const FrameProcessor&) = delete;
  FrameProcessor& operator=(const FrameProcessor&) = delete;

  // Makes `frame` the rest state (status reference, or skipped/lost on failure).
  FrameResult setReference(const cv::Mat& frame, double t = 0);
  // Processes the next frame; the first one becomes the reference if none is set.
  FrameResult process(const cv::Mat& frame, double t);
  // Re-zeroes the 6-D output (a new contact starts from here).
  void rezero();

  bool hasReference() const;
  const MarkerField& restMarkers() const;     // S
  const SensorFrame& sensorFrame() const;     // S from L
  const StereoCalibration& calibration() const;
  const MarkerPattern& pattern() const;
  // Each view's tracked 2-D markers after the last frame (view pixels, after
  // the view's flip; valid where measured in that frame), e.g. for display.
  const vision::ViewMarkers& leftViewMarkers() const;
  const vision::ViewMarkers& rightViewMarkers() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace onetip::pipeline
