#include "sim_replay.hpp"

#include <random>

#include "sim/random_scenario.hpp"
#include "sim/simulator.hpp"

namespace onetip::poseval {

sim::Scenario sampleScenario(const std::string& name) {
  return sim::loadScenario(std::string(ONETIP_SOURCE_DIR) + "/samples/scenarios/" + name + ".yaml");
}

namespace {

MarkerField perturbed(const MarkerField& exact, double noise_mm, double drop_fraction, std::mt19937& rng) {
  MarkerField out = exact;
  std::normal_distribution<double> noise(0.0, noise_mm > 0 ? noise_mm : 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int i = 0; i < out.size(); ++i) {
    const size_t k = static_cast<size_t>(i);
    if (noise_mm > 0) out.position[k] += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
    if (drop_fraction > 0 && uniform(rng) < drop_fraction) out.valid[k] = 0;
  }
  return out;
}

}  // namespace

Recording record(const sim::Scenario& scenario, const ReplayOptions& options) {
  sim::Simulator simulator(scenario);
  std::mt19937 rng(options.seed);
  Recording out;
  out.marker_depth_mm = simulator.pattern().marker_depth_mm;
  out.rest = perturbed(simulator.restMarkers(), options.noise_mm, 0.0, rng);
  while (!simulator.done()) {
    const sim::GroundTruthFrame& f = simulator.next();
    out.frames.push_back(perturbed(f.markers, options.noise_mm, options.drop_fraction, rng));
    out.truth.push_back(f);
  }
  return out;
}

ReplayFrame replayFrame(const sim::GroundTruthFrame& f, const input::TrackerResult& r, int marker_count) {
  ReplayFrame out;
  out.t = f.t;
  out.gt_contact = f.in_contact;
  out.gt_state = f.state;
  out.gt = f.input;
  out.gt_c0 = f.onset_centroid;
  out.gt_contact_markers = f.contact;
  out.gt_slip = f.slip;
  out.gt_positions = f.markers.position;
  if (f.indenter_poses.size() > 1) {
    out.gt_followed.assign(f.owner.size(), 0);
    for (size_t i = 0; i < f.owner.size(); ++i) out.gt_followed[i] = f.owner[i] == f.followed ? 1 : 0;
  }
  Eigen::Vector2d sum{0, 0};
  int touching = 0;
  for (size_t i = 0; i < f.contact.size() && i < f.markers.position.size(); ++i)
    if (f.contact[i]) {
      sum += f.markers.position[i].head<2>();
      ++touching;
    }
  out.gt_footprint_valid = touching > 0;
  if (touching > 0) out.gt_footprint = sum / touching;
  out.contact = r.contact;
  out.state = r.state;
  out.raw = r.raw;
  out.sd = r.sd;
  out.composed = r.composed;
  out.euler_sum = r.euler_sum;
  out.out_of_range = r.out_of_range;
  out.model = r.step.model;
  out.n_stick = r.step.n_stick;
  out.n_slip = r.step.n_slip;
  out.regions = static_cast<int>(r.field.regions.size());
  out.region.assign(static_cast<size_t>(marker_count), 0);
  out.slip.assign(static_cast<size_t>(marker_count), 0);
  out.stick.assign(static_cast<size_t>(marker_count), 0);
  if (r.step.active) {
    for (int id : r.field.regions[static_cast<size_t>(r.step.region)].markers) out.region[static_cast<size_t>(id)] = 1;
    out.region_markers = static_cast<int>(r.field.regions[static_cast<size_t>(r.step.region)].markers.size());
    for (size_t i = 0; i < r.step.labels.size(); ++i) {
      out.slip[i] = r.step.labels[i] == contact::MarkerLabel::slip ? 1 : 0;
      out.stick[i] = r.step.labels[i] == contact::MarkerLabel::stick ? 1 : 0;
    }
  }
  for (const auto& e : r.events) out.events.push_back(e.type);
  return out;
}

std::vector<ReplayFrame> track(const Recording& recording, input::PoseTrackerOptions options) {
  options.marker_depth_mm = recording.marker_depth_mm;
  input::PoseTracker tracker(options);
  std::vector<ReplayFrame> frames;
  for (size_t k = 0; k < recording.frames.size(); ++k) {
    const MarkerField& now = recording.frames[k];
    frames.push_back(replayFrame(recording.truth[k], tracker.update(now, recording.rest, recording.truth[k].t), now.size()));
  }
  return frames;
}

std::vector<ReplayFrame> replay(const sim::Scenario& scenario, const ReplayOptions& options) {
  return track(record(scenario, options), options.tracker);
}

std::vector<ReplayFrame> replayCampaignRun(unsigned seed) {
  const sim::RandomScenario rs = sim::randomScenario(seed);
  ReplayOptions o;
  o.noise_mm = 0.0003 * rs.conditions.noise_grey;
  o.seed = seed;
  return replay(rs.scenario, o);
}

}  // namespace onetip::poseval
