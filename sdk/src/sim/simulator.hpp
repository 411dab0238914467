// sim/simulator.hpp — the digital twin: a scenario played frame by frame.
//
// Field level (always): the contact model advanced to each frame's time, the
// markers' exact 3-D positions in S, per-marker contact and slip labels and the
// 6-D ground truth. Image level (render()): what the virtual binocular camera
// sees, 1920 x 1080 grey by default. Calibration scenarios show a rigid target
// at random poses instead of the pad (markers then hold the target corners).
// S is derived from the rest markers (docs/reference.md); for a flat pad it is
// the pad frame P itself.
#pragma once

#include <memory>
#include <opencv2/core.hpp>

#include "core/calibration.hpp"
#include "core/pattern.hpp"
#include "sim/ground_truth.hpp"
#include "sim/scenario.hpp"

namespace onetip::sim {

struct SimulatorOptions {
  int frames = 0;         // 0: the scenario's own count (duration * fps + 1)
  int seed = -1;          // -1: the scenario's seed (image noise and random poses)
  void validate() const;
};

class Simulator {
 public:
  explicit Simulator(Scenario scenario, SimulatorOptions options = {});
  ~Simulator();
  Simulator(const Simulator&) = delete;
  Simulator& operator=(const Simulator&) = delete;

  int frameCount() const;
  bool done() const;
  // Advances to the next frame and returns its ground truth.
  const GroundTruthFrame& next();
  // Interactive driving (the viewer's virtual finger): advances one frame,
  // 1 / fps after the current one, with indenter i posed by poses[i] (x, y,
  // depth, yaw, pitch, roll as in a keyframe; its t is ignored) instead of the
  // scenario's keyframes. Not bounded by frameCount(). Throws InputError for a
  // calibration scenario or when poses.size() differs from the indenter count.
  const GroundTruthFrame& nextPosed(const std::vector<Keyframe>& poses);
  const GroundTruthFrame& current() const;
  // Renders the current frame (call after next()).
  cv::Mat render() const;
  // Changes the image effects from the next render() on (e.g. an occlusion that
  // appears mid-run); throws InputError for invalid effects.
  void setImageEffects(const ImageEffects& effects);

  const Scenario& scenario() const;
  StereoCalibration calibration() const;      // exact calibration of the virtual cameras
  MarkerPattern pattern() const;              // the pad's (or the calibration target's) pattern
  const MarkerField& restMarkers() const;     // S

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace onetip::sim
