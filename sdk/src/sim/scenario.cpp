#include "sim/scenario.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

#include "core/config_file.hpp"
#include "core/error.hpp"
#include "core/rotation.hpp"

namespace onetip::sim {

namespace {

constexpr double kLimit = 1e6;  // beyond every scenario value's range: larger is a typo, not a setting

// A map of the scenario file with its known keys. `check` runs after each
// value is read into its options, so a value the options refuse is reported
// at its own key and line (the defaults are valid: the first failure belongs
// to the key just read).
class Section {
 public:
  Section(ConfigNode node, const std::set<std::string>& known, std::function<void()> check = {})
      : node_(std::move(node)), check_(std::move(check)) {
    node_.allowOnly(known);
  }
  ConfigNode operator[](const std::string& key) const { return node_[key]; }
  void read(const std::string& key, double& out) const {
    readWith(key, [&](const ConfigNode& n) { out = n.real(-kLimit, kLimit); });
  }
  void read(const std::string& key, int& out) const {
    readWith(key, [&](const ConfigNode& n) { out = n.integer(-10000000, 10000000); });
  }
  void read(const std::string& key, bool& out) const {
    readWith(key, [&](const ConfigNode& n) { out = n.flag(); });
  }
  // Reads `key` (when present) with `assign`, whose errors name the file,
  // line and key (ConfigNode's do), then runs the section's check.
  template <typename F>
  void readWith(const std::string& key, F&& assign) const {
    const ConfigNode n = node_[key];
    if (!n.present()) return;
    assign(n);
    if (!check_) return;
    try {
      check_();
    } catch (const InputError& e) {
      n.fail(e.what());
    }
  }

 private:
  ConfigNode node_;
  std::function<void()> check_;
};

PadOptions readPad(const ConfigNode& node) {
  PadOptions p;
  const Section s(node,
                  {"rows", "cols", "square_mm", "thickness_mm", "marker_depth_mm", "dome_radius_mm",
                   "nodes_per_square", "margin_squares", "friction", "contact_model", "kinetic_ratio",
                   "foundation_length_mm"},
                  [&] { p.validate(); });
  s.read("rows", p.pattern.rows);
  s.read("cols", p.pattern.cols);
  s.read("square_mm", p.pattern.square_mm);
  s.read("thickness_mm", p.thickness_mm);
  s.read("marker_depth_mm", p.pattern.marker_depth_mm);
  s.read("dome_radius_mm", p.dome_radius_mm);
  s.read("nodes_per_square", p.nodes_per_square);
  s.read("margin_squares", p.margin_squares);
  s.read("friction", p.friction);
  s.readWith("contact_model", [&](const ConfigNode& n) {
    const std::string model = n.text();
    const auto kind = contactModelFromString(model);
    if (!kind) n.fail("expected 'halfspace' or 'foundation', got \"" + model + "\"");
    p.contact_model = *kind;
  });
  s.read("kinetic_ratio", p.kinetic_ratio);
  s.read("foundation_length_mm", p.foundation_length_mm);
  return p;
}

CameraRigOptions readCamera(const ConfigNode& node) {
  CameraRigOptions c;
  const Section s(node,
                  {"view_width", "view_height", "focal_px", "distance_mm", "baseline_mm", "k1", "k2", "p1", "p2",
                   "k3", "flip_left", "flip_right"},
                  [&] { c.validate(); });
  s.read("view_width", c.view_width);
  s.read("view_height", c.view_height);
  s.read("focal_px", c.focal_px);
  s.read("distance_mm", c.distance_mm);
  s.read("baseline_mm", c.baseline_mm);
  s.read("k1", c.k1);
  s.read("k2", c.k2);
  s.read("p1", c.p1);
  s.read("p2", c.p2);
  s.read("k3", c.k3);
  s.read("flip_left", c.flip_left);
  s.read("flip_right", c.flip_right);
  return c;
}

ImageEffects readImage(const ConfigNode& node) {
  ImageEffects e;
  const Section s(node,
                  {"noise_sigma", "blur_sigma", "vignetting", "exposure", "light_gradient", "dust_blobs",
                   "specular_spots", "occlusion_fraction"},
                  [&] { e.validate(); });
  s.read("noise_sigma", e.noise_sigma);
  s.read("blur_sigma", e.blur_sigma);
  s.read("vignetting", e.vignetting);
  s.read("exposure", e.exposure);
  s.read("light_gradient", e.light_gradient);
  s.read("dust_blobs", e.dust_blobs);
  s.read("specular_spots", e.specular_spots);
  s.read("occlusion_fraction", e.occlusion_fraction);
  return e;
}

// The world effects (sim/world_effects.hpp): each section off when absent.
ViscoelasticOptions readViscoelastic(const ConfigNode& node) {
  ViscoelasticOptions v;
  const Section s(node, {"relaxation", "time_s"}, [&] { v.validate(); });
  s.read("relaxation", v.relaxation);
  s.read("time_s", v.time_s);
  return v;
}

RestDriftOptions readDrift(const ConfigNode& node) {
  RestDriftOptions d;
  const Section s(node, {"expansion", "offset_mm", "time_s"}, [&] { d.validate(); });
  s.read("expansion", d.expansion);
  s.readWith("offset_mm", [&](const ConfigNode& n) {
    const auto o = n.reals(3, -kLimit, kLimit);
    d.offset_mm = {o[0], o[1], o[2]};
  });
  s.read("time_s", d.time_s);
  return d;
}

CameraShiftOptions readCameraShift(const ConfigNode& node) {
  CameraShiftOptions c;
  const Section s(node, {"px", "at_s", "ramp_s", "view"}, [&] { c.validate(); });
  s.readWith("px", [&](const ConfigNode& n) {
    const auto p = n.reals(2, -kLimit, kLimit);
    c.shift_px = {p[0], p[1]};
  });
  s.read("at_s", c.at_s);
  s.read("ramp_s", c.ramp_s);
  s.readWith("view", [&](const ConfigNode& n) {
    if (!cameraShiftViewsFromString(n.text(), c.views)) n.fail("expected 'both', 'left' or 'right'");
  });
  return c;
}

MarkerDamageOptions readDamage(const ConfigNode& node, const MarkerPattern& pattern) {
  MarkerDamageOptions d;
  const Section s(node, {"ids", "fraction", "seed", "radius"}, [&] { d.validate(); });
  s.readWith("ids", [&](const ConfigNode& n) {
    if (!n.isSeq()) n.fail("expected a list of marker ids");
    for (size_t i = 0; i < n.size(); ++i) d.ids.push_back(n[i].integer(0, pattern.count() - 1));
  });
  s.read("fraction", d.fraction);
  s.readWith("seed", [&](const ConfigNode& n) { d.seed = static_cast<unsigned>(n.integer(0, 2147483647)); });
  s.read("radius", d.radius);
  return d;
}

LightFlickerOptions readLight(const ConfigNode& node) {
  LightFlickerOptions l;
  const Section s(node, {"flicker", "exposure_step", "step_at_s"}, [&] { l.validate(); });
  s.read("flicker", l.flicker);
  s.read("exposure_step", l.exposure_step);
  s.read("step_at_s", l.step_at_s);
  return l;
}

CalibrationTarget readTarget(const ConfigNode& node) {
  CalibrationTarget g;
  const Section s(node,
                  {"rows", "cols", "square_mm", "poses", "tilt_deg", "yaw_deg", "shift_mm", "depth_min_mm",
                   "depth_max_mm"},
                  [&] { MarkerPattern{g.rows, g.cols, g.square_mm}.validate(); });
  s.read("rows", g.rows);
  s.read("cols", g.cols);
  s.read("square_mm", g.square_mm);
  s.readWith("poses", [&](const ConfigNode& n) { g.poses = n.integer(3, 1000); });
  s.readWith("tilt_deg", [&](const ConfigNode& n) { g.tilt_deg = n.real(0, 60); });
  s.read("yaw_deg", g.yaw_deg);
  s.read("shift_mm", g.shift_mm);
  s.read("depth_min_mm", g.depth_min_mm);
  s.read("depth_max_mm", g.depth_max_mm);
  if (!(g.depth_min_mm < g.depth_max_mm)) node["depth_min_mm"].fail("must be less than depth_max_mm");
  return g;
}

IndenterTrack readIndenter(const ConfigNode& node) {
  IndenterTrack track;
  IndenterGeometry& g = track.geometry;
  const Section s(node, {"shape", "semi_axes", "radius", "size", "pivot", "keyframes"}, [&] { g.validate(); });
  s.readWith("shape", [&](const ConfigNode& n) {
    try {
      g.shape = IndenterGeometry::shapeFromName(n.text());
    } catch (const InputError& e) {
      n.fail(e.what());
    }
  });
  if (g.shape == IndenterShape::ellipsoid)
    s.readWith("semi_axes", [&](const ConfigNode& n) {
      const auto a = n.reals(3, -kLimit, kLimit);
      g.semi_axes = {a[0], a[1], a[2]};
    });
  if (g.shape == IndenterShape::sphere) {
    g.semi_axes = {6.0, 6.0, 6.0};
    s.readWith("radius", [&](const ConfigNode& n) {
      const double r = n.real(-kLimit, kLimit);
      g.semi_axes = {r, r, r};
    });
  }
  if (g.shape == IndenterShape::plate)
    s.readWith("size", [&](const ConfigNode& n) {
      const auto a = n.reals(2, -kLimit, kLimit);
      g.plate_width = a[0];
      g.plate_length = a[1];
    });
  // Beyond the body's own size a pivot only makes the indenter sweep the
  // pad at huge speeds (and the contact model sub-step without end).
  s.readWith("pivot", [&](const ConfigNode& n) {
    const auto p = n.reals(3, -50, 50);
    track.pivot = {p[0], p[1], p[2]};
  });
  const ConfigNode kf = s["keyframes"];
  if (!kf.isSeq() || kf.size() < 1) kf.fail("expected a list of keyframes");
  Keyframe prev;
  for (size_t i = 0; i < kf.size(); ++i) {
    const ConfigNode k = kf[i];
    k.allowOnly({"t", "x", "y", "depth", "yaw", "pitch", "roll"});
    Keyframe f = prev;
    f.t = k["t"].real(0, 3600);
    if (i > 0 && !(f.t > prev.t)) k["t"].fail("must be greater than the previous keyframe's t");
    f.x = k.real("x", prev.x, -30, 30);
    f.y = k.real("y", prev.y, -30, 30);
    f.depth = k.real("depth", prev.depth, -30, 6);
    f.yaw = k.real("yaw", prev.yaw, -90, 90);
    f.pitch = k.real("pitch", prev.pitch, -80, 80);
    f.roll = k.real("roll", prev.roll, -80, 80);
    track.keyframes.push_back(f);
    prev = f;
  }
  return track;
}

}  // namespace

Keyframe IndenterTrack::at(double t) const {
  if (t <= keyframes.front().t) return keyframes.front();
  if (t >= keyframes.back().t) return keyframes.back();
  auto hi = std::upper_bound(keyframes.begin(), keyframes.end(), t,
                             [](double v, const Keyframe& k) { return v < k.t; });
  const Keyframe& b = *hi;
  const Keyframe& a = *(hi - 1);
  const double s = (t - a.t) / (b.t - a.t);
  auto mix = [s](double p, double q) { return p + s * (q - p); };
  return {t, mix(a.x, b.x), mix(a.y, b.y), mix(a.depth, b.depth), mix(a.yaw, b.yaw), mix(a.pitch, b.pitch),
          mix(a.roll, b.roll)};
}

double Scenario::duration() const {
  double d = 0;
  for (const auto& tr : indenters) d = std::max(d, tr.keyframes.back().t);
  return d;
}

int Scenario::defaultFrameCount() const {
  if (isCalibration()) return target.poses;
  return static_cast<int>(std::floor(duration() * fps + 1e-9)) + 1;
}

std::vector<Eigen::Isometry3d> Scenario::posesAt(double t, const PadLattice& lattice) const {
  std::vector<Eigen::Isometry3d> poses;
  for (const auto& tr : indenters) {
    const Keyframe k = tr.at(t);
    Eigen::Isometry3d pose = rigidFromTranslationYawPitchRoll(Eigen::Vector3d(k.x, k.y, 0), k.yaw * kRadPerDeg,
                                                              k.pitch * kRadPerDeg, k.roll * kRadPerDeg);
    pose.translation() -= pose.linear() * tr.pivot;  // rotate about the pivot
    const double surface = lattice.options().pattern.marker_depth_mm - lattice.domeOffset(k.x, k.y);
    pose.translation().z() += surface - k.depth - lowestZ(tr.geometry, pose);
    poses.push_back(pose);
  }
  return poses;
}

Scenario loadScenario(const std::string& path) {
  const ConfigNode root = ConfigNode::load(path);
  root.allowOnly({"name", "description", "kind", "fps", "seed", "pad", "camera", "image", "indenters", "target",
                  "viscoelastic", "drift", "camera_shift", "damage", "light"});
  Scenario sc;
  sc.name = root["name"].text();
  if (sc.name.empty()) root["name"].fail("must not be empty");
  sc.description = root.text("description", "");
  sc.kind = root.text("kind", "touch");
  if (sc.kind != "touch" && sc.kind != "calibration") root["kind"].fail("expected 'touch' or 'calibration'");
  sc.fps = root.real("fps", 30, 1, 1000);
  sc.seed = static_cast<unsigned>(root.integer("seed", 1, 0, 2147483647));
  sc.pad = readPad(root["pad"]);
  sc.camera = readCamera(root["camera"]);
  sc.image = readImage(root["image"]);
  sc.world.viscoelastic = readViscoelastic(root["viscoelastic"]);
  sc.world.drift = readDrift(root["drift"]);
  sc.world.camera_shift = readCameraShift(root["camera_shift"]);
  sc.world.damage = readDamage(root["damage"], sc.pad.pattern);
  sc.world.light = readLight(root["light"]);
  if (sc.isCalibration()) {
    sc.target = readTarget(root["target"]);
    return sc;
  }
  const ConfigNode ind = root["indenters"];
  if (!ind.isSeq() || ind.size() < 1) ind.fail("expected a list of at least one indenter");
  for (size_t i = 0; i < ind.size(); ++i) sc.indenters.push_back(readIndenter(ind[i]));
  if (sc.defaultFrameCount() > kMaxScenarioFrames)
    root["fps"].fail("fps x duration gives " + std::to_string(sc.defaultFrameCount()) + " frames; at most " +
                     std::to_string(kMaxScenarioFrames) + " are allowed");
  return sc;
}

}  // namespace onetip::sim
