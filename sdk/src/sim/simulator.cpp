#include "sim/simulator.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "core/error.hpp"
#include "core/rotation.hpp"
#include "core/sensor_frame.hpp"
#include "sim/contact_model.hpp"
#include "sim/sheet_builder.hpp"
#include "sim/viscoelastic_layer.hpp"

namespace onetip::sim {

namespace {
constexpr double kRenderSpacingMm = 0.15;  // fine render lattice (~5 px at the default camera)

std::vector<Eigen::Isometry3d> randomTargetPoses(const CalibrationTarget& t, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> tilt(-t.tilt_deg, t.tilt_deg), yaw(-t.yaw_deg, t.yaw_deg),
      shift(-t.shift_mm, t.shift_mm), depth(t.depth_min_mm, t.depth_max_mm);
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < t.poses; ++i)
    poses.push_back(rigidFromTranslationYawPitchRoll({shift(rng), shift(rng), depth(rng)}, yaw(rng) * kRadPerDeg,
                                                     tilt(rng) * kRadPerDeg, tilt(rng) * kRadPerDeg));
  return poses;
}
}  // namespace

void SimulatorOptions::validate() const {
  if (frames < 0 || frames > 1000000) throw InputError("frames: must be in [0, 1000000]");
  if (seed < -1) throw InputError("seed: must be >= 0");
}

struct Simulator::Impl {
  Scenario sc;
  SimulatorOptions opt;
  unsigned seed;
  std::unique_ptr<PadLattice> lattice;
  std::unique_ptr<ContactModel> model;
  CameraRig rig;
  std::unique_ptr<FrameRenderer> renderer;
  Eigen::Isometry3d S_from_P = Eigen::Isometry3d::Identity();
  MarkerField rest;
  GroundTruthPose gt_pose;
  GroundTruthFrame frame;
  std::vector<Eigen::Isometry3d> target_poses;  // calibration scenes (P)
  int index = -1;
  // World effects (sim/world_effects.hpp); all idle when the scenario has none.
  std::unique_ptr<ViscoelasticLayer> layer;     // set when the gel relaxes
  std::vector<Eigen::Vector3d> elastic;         // the contact model's own displacements, per node (with layer)
  std::vector<int> hidden;                      // marker ids hidden for good
  double layer_t = 0;                           // time the layer was last advanced to

  // A node's rest point (P) at time t, drifted if the scenario drifts.
  Eigen::Vector3d restAt(int node, double t) const {
    const Eigen::Vector3d p = lattice->markerLayerRest(node);
    return sc.world.drift.enabled() ? sc.world.drift.apply(p, t) : p;
  }
  // A node's displacement (P): elastic, or elastic + delayed with the layer.
  Eigen::Vector3d displacementOf(int node) const {
    return layer ? layer->total()[static_cast<size_t>(node)] : model->displacement(node);
  }

  MarkerPattern pattern() const {
    if (sc.isCalibration()) return {sc.target.rows, sc.target.cols, sc.target.square_mm};
    return sc.pad.pattern;
  }
  int frames() const { return opt.frames > 0 ? opt.frames : sc.defaultFrameCount(); }
  double timeOf(int k) const {
    const int n = frames();
    if (opt.frames > 0 && n > 1) return sc.duration() * k / (n - 1);
    return k / sc.fps;
  }

  void fillTouchFrame(double t, const std::vector<Eigen::Isometry3d>& poses) {
    frame.t = t;
    model->advance(poses);
    if (layer) {
      elastic = model->allDisplacements();
      layer->advance(elastic, std::max(0.0, t - layer_t));
      layer_t = t;
    }
    const MarkerPattern p = sc.pad.pattern;
    for (int id = 0; id < p.count(); ++id) {
      const int node = lattice->nodeOfMarker(id);
      frame.markers.set(id, S_from_P * (restAt(node, t) + displacementOf(node)));
      const auto& c = model->node(node);
      frame.contact[static_cast<size_t>(id)] = c.contact;
      frame.slip[static_cast<size_t>(id)] = c.contact && c.slip;
      frame.owner[static_cast<size_t>(id)] = c.contact ? c.owner : -1;
    }
    frame.state = model->state();
    frame.indenter_nodes.assign(poses.size(), 0);
    for (int node : model->activeNodes()) {
      const NodeContact& c = model->node(node);
      if (c.contact && c.owner >= 0 && static_cast<size_t>(c.owner) < poses.size())
        ++frame.indenter_nodes[static_cast<size_t>(c.owner)];
    }
    frame.indenter_poses.clear();
    for (const auto& T : poses) frame.indenter_poses.push_back(S_from_P * T);
    for (int id : hidden) frame.markers.valid[static_cast<size_t>(id)] = 0;
    if (!layer && !sc.world.drift.enabled()) {
      gt_pose.update(frame, rest);
      return;
    }
    // The truth's contact rule on what the indenters do now, against the rest as it is now (ground_truth.hpp).
    MarkerField rest_now(p), deformed(p);
    for (int id = 0; id < p.count(); ++id) {
      const int node = lattice->nodeOfMarker(id);
      const Eigen::Vector3d r = restAt(node, t);
      rest_now.set(id, S_from_P * r);
      deformed.set(id, S_from_P * (r + (layer ? elastic[static_cast<size_t>(node)] : model->displacement(node))));
    }
    gt_pose.update(frame, rest_now, deformed);
  }

  void fillCalibrationFrame(int k) {
    frame.t = k / sc.fps;
    const MarkerPattern p = pattern();
    const Eigen::Isometry3d& pose = target_poses[static_cast<size_t>(k % target_poses.size())];
    for (int r = 0; r < p.rows; ++r)
      for (int c = 0; c < p.cols; ++c)
        frame.markers.set(p.id(r, c), pose * Eigen::Vector3d((c - 0.5 * (p.cols - 1)) * p.square_mm,
                                                             (r - 0.5 * (p.rows - 1)) * p.square_mm, 0));
    frame.indenter_poses = {pose};
  }

  CheckerTexture texture() const {
    const MarkerPattern p = pattern();
    CheckerTexture t;
    t.rows = p.rows;
    t.cols = p.cols;
    t.square_mm = p.square_mm;
    t.border_mm = p.square_mm;
    return t;
  }
};

Simulator::Simulator(Scenario scenario, SimulatorOptions options) : impl_(std::make_unique<Impl>()) {
  options.validate();
  Impl& m = *impl_;
  m.sc = std::move(scenario);
  m.opt = options;
  m.seed = options.seed >= 0 ? static_cast<unsigned>(options.seed) : m.sc.seed;
  m.rig = CameraRig::fromOptions(m.sc.camera);
  m.renderer = std::make_unique<FrameRenderer>(m.rig);
  const MarkerPattern p = m.pattern();
  m.frame.markers = MarkerField(p);
  m.frame.contact.assign(static_cast<size_t>(p.count()), 0);
  m.frame.slip.assign(static_cast<size_t>(p.count()), 0);
  m.frame.owner.assign(static_cast<size_t>(p.count()), -1);
  if (m.sc.isCalibration()) {
    m.target_poses = randomTargetPoses(m.sc.target, m.seed);
    m.rest = MarkerField(p);
    return;
  }
  m.lattice = std::make_unique<PadLattice>(m.sc.pad);
  std::vector<IndenterGeometry> shapes;
  for (const auto& tr : m.sc.indenters) shapes.push_back(tr.geometry);
  m.model = std::make_unique<ContactModel>(*m.lattice, shapes);
  m.model->reset(m.sc.posesAt(0.0, *m.lattice));
  if (m.sc.world.viscoelastic.enabled())
    m.layer = std::make_unique<ViscoelasticLayer>(m.sc.world.viscoelastic, m.lattice->nodeCount());
  m.sc.world.drift.validate();
  m.sc.world.camera_shift.validate();
  m.sc.world.light.validate();
  m.sc.world.damage.validate();
  m.hidden = m.sc.world.damage.hiddenIds(p);
  MarkerField rest_P(p);
  for (int id = 0; id < p.count(); ++id) rest_P.set(id, m.lattice->markerLayerRest(m.lattice->nodeOfMarker(id)));
  // S from the rest markers as the SDK derives it; the camera "L" here is P
  // seen from below, so hand the fit points expressed with the camera at -z.
  Eigen::Isometry3d camera_below = Eigen::Isometry3d::Identity();
  camera_below.translation() = Eigen::Vector3d(0, 0, m.sc.camera.distance_mm);
  const SensorFrame S = SensorFrame::fromRestMarkers(
      SensorFrame(camera_below).toSensor(rest_P));  // points in a frame whose origin is below the pad
  m.S_from_P = S.sensorFromLeft() * camera_below;
  m.rest = SensorFrame(m.S_from_P).toSensor(rest_P);
}

Simulator::~Simulator() = default;

int Simulator::frameCount() const { return impl_->frames(); }
bool Simulator::done() const { return impl_->index + 1 >= impl_->frames(); }

const GroundTruthFrame& Simulator::next() {
  Impl& m = *impl_;
  if (done()) throw std::logic_error("Simulator::next: past the last frame");
  ++m.index;
  m.frame.index = m.index;
  if (m.sc.isCalibration())
    m.fillCalibrationFrame(m.index);
  else
    m.fillTouchFrame(m.timeOf(m.index), m.sc.posesAt(m.timeOf(m.index), *m.lattice));
  return m.frame;
}

const GroundTruthFrame& Simulator::nextPosed(const std::vector<Keyframe>& poses) {
  Impl& m = *impl_;
  if (m.sc.isCalibration()) throw InputError("Simulator::nextPosed: a calibration scenario has no indenter to pose");
  if (poses.size() != m.sc.indenters.size())
    throw InputError("Simulator::nextPosed: " + std::to_string(poses.size()) + " poses for " +
                     std::to_string(m.sc.indenters.size()) + " indenters");
  // The scenario's own pose rule (pivot, depth below the dome) on one-keyframe tracks.
  Scenario posed = m.sc;
  for (size_t i = 0; i < poses.size(); ++i) posed.indenters[i].keyframes = {poses[i]};
  const double t = m.index < 0 ? 0.0 : m.frame.t + 1.0 / m.sc.fps;
  ++m.index;
  m.frame.index = m.index;
  m.fillTouchFrame(t, posed.posesAt(t, *m.lattice));
  return m.frame;
}

const GroundTruthFrame& Simulator::current() const { return impl_->frame; }

cv::Mat Simulator::render() const {
  const Impl& m = *impl_;
  std::vector<CheckerSheet> sheets;
  if (m.sc.isCalibration()) {
    sheets.push_back(rigidBoard(m.texture(), m.frame.indenter_poses.front(), kRenderSpacingMm));
  } else {
    const auto u = m.layer ? m.layer->total() : m.model->allDisplacements();
    std::vector<Eigen::Vector3d> nodes(u.size());
    for (int i = 0; i < m.lattice->nodeCount(); ++i)
      nodes[static_cast<size_t>(i)] = m.S_from_P * (m.restAt(i, m.frame.t) + u[static_cast<size_t>(i)]);
    const int factor = std::max(1, static_cast<int>(std::lround(m.lattice->spacing() / kRenderSpacingMm)));
    sheets.push_back(refineLattice(nodes, m.lattice->nu(), m.lattice->nv(), m.lattice->u0(), m.lattice->v0(),
                                   m.lattice->spacing(), factor, m.texture()));
  }
  const std::uint64_t frame_seed = static_cast<std::uint64_t>(m.seed) * 1000003ull + static_cast<std::uint64_t>(m.index);
  ImageEffects effects = m.sc.image;
  effects.layout_seed = m.seed;  // dust, spots and occluders stay put for the whole run
  const WorldEffects& w = m.sc.world;
  if (w.light.enabled())  // within the exposure's own range, where the sensor clips anyway
    effects.exposure = std::clamp(effects.exposure * w.light.gain(m.frame.t, m.seed, m.index), 0.2, 3.0);
  ViewDisturbances disturbances;
  for (int view = 0; view < 2; ++view)
    disturbances.shift_px[static_cast<size_t>(view)] = w.camera_shift.shiftAt(m.frame.t, view);
  for (int id : m.hidden) disturbances.smudges.push_back(m.frame.markers.position[static_cast<size_t>(id)]);
  const CheckerTexture texture = m.texture();
  disturbances.smudge_radius_mm = w.damage.radius * texture.square_mm;
  disturbances.smudge_grey = static_cast<float>(0.5 * (texture.dark + texture.light));
  return m.renderer->render(sheets, effects, frame_seed, disturbances);
}

void Simulator::setImageEffects(const ImageEffects& effects) {
  effects.validate();
  impl_->sc.image = effects;
}

const Scenario& Simulator::scenario() const { return impl_->sc; }
StereoCalibration Simulator::calibration() const { return impl_->rig.calibration(); }
MarkerPattern Simulator::pattern() const { return impl_->pattern(); }
const MarkerField& Simulator::restMarkers() const { return impl_->rest; }

}  // namespace onetip::sim
