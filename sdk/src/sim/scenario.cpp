#include "sim/scenario.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/error.hpp"
#include "core/filestorage_io.hpp"
#include "core/rotation.hpp"

namespace onetip::sim {

namespace {

// A FileStorage map with the path used in error messages and a set of known keys.
class Section {
 public:
  Section(cv::FileNode node, std::string where, std::set<std::string> known)
      : node_(std::move(node)), where_(std::move(where)) {
    if (node_.empty() || node_.isNone()) return;
    if (!node_.isMap()) throw InputError(where_ + ": expected a map");
    for (const auto& k : node_.keys())
      if (!known.count(k)) throw InputError(where_ + "." + k + ": unknown key");
  }
  bool has(const std::string& key) const { return !node_.empty() && !node_[key].empty() && !node_[key].isNone(); }
  double number(const std::string& key, double fallback) const {
    if (!has(key)) return fallback;
    const cv::FileNode n = node_[key];
    if (!n.isReal() && !n.isInt()) throw InputError(where_ + "." + key + ": expected a number");
    const double v = static_cast<double>(n);
    if (!std::isfinite(v)) throw InputError(where_ + "." + key + ": must be finite");
    return v;
  }
  int integer(const std::string& key, int fallback) const {
    const double v = number(key, fallback);
    if (v != std::floor(v) || std::abs(v) > 1e7) throw InputError(where_ + "." + key + ": expected an integer");
    return static_cast<int>(v);
  }
  std::string text(const std::string& key, const std::string& fallback) const {
    if (!has(key)) return fallback;
    if (!node_[key].isString()) throw InputError(where_ + "." + key + ": expected a string");
    return static_cast<std::string>(node_[key]);
  }
  std::vector<double> numbers(const std::string& key, size_t count) const {
    const cv::FileNode n = node_[key];
    if (!n.isSeq() || n.size() != count)
      throw InputError(where_ + "." + key + ": expected a list of " + std::to_string(count) + " numbers");
    std::vector<double> v;
    for (const auto& e : n) {
      if (!e.isReal() && !e.isInt()) throw InputError(where_ + "." + key + ": expected numbers");
      v.push_back(static_cast<double>(e));
    }
    return v;
  }
  const cv::FileNode& node() const { return node_; }
  const std::string& where() const { return where_; }

 private:
  cv::FileNode node_;
  std::string where_;
};

// Re-throws a validate() error with the file and section in front.
template <typename F>
void validateIn(const std::string& where, F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    throw InputError(where + ": " + e.what());
  }
}

PadOptions readPad(const Section& s) {
  PadOptions p;
  p.pattern.rows = s.integer("rows", p.pattern.rows);
  p.pattern.cols = s.integer("cols", p.pattern.cols);
  p.pattern.square_mm = s.number("square_mm", p.pattern.square_mm);
  p.thickness_mm = s.number("thickness_mm", p.thickness_mm);
  p.marker_depth_mm = s.number("marker_depth_mm", p.marker_depth_mm);
  p.dome_radius_mm = s.number("dome_radius_mm", p.dome_radius_mm);
  p.nodes_per_square = s.integer("nodes_per_square", p.nodes_per_square);
  p.margin_squares = s.integer("margin_squares", p.margin_squares);
  p.friction = s.number("friction", p.friction);
  validateIn(s.where(), [&] { p.validate(); });
  return p;
}

CameraRigOptions readCamera(const Section& s) {
  CameraRigOptions c;
  c.view_width = s.integer("view_width", c.view_width);
  c.view_height = s.integer("view_height", c.view_height);
  c.focal_px = s.number("focal_px", c.focal_px);
  c.distance_mm = s.number("distance_mm", c.distance_mm);
  c.baseline_mm = s.number("baseline_mm", c.baseline_mm);
  c.k1 = s.number("k1", c.k1);
  c.k2 = s.number("k2", c.k2);
  c.p1 = s.number("p1", c.p1);
  c.p2 = s.number("p2", c.p2);
  c.k3 = s.number("k3", c.k3);
  c.flip_left = s.integer("flip_left", c.flip_left) != 0;
  c.flip_right = s.integer("flip_right", c.flip_right) != 0;
  validateIn(s.where(), [&] { c.validate(); });
  return c;
}

ImageEffects readImage(const Section& s) {
  ImageEffects e;
  e.noise_sigma = s.number("noise_sigma", e.noise_sigma);
  e.blur_sigma = s.number("blur_sigma", e.blur_sigma);
  e.vignetting = s.number("vignetting", e.vignetting);
  e.exposure = s.number("exposure", e.exposure);
  e.light_gradient = s.number("light_gradient", e.light_gradient);
  e.dust_blobs = s.integer("dust_blobs", e.dust_blobs);
  e.specular_spots = s.integer("specular_spots", e.specular_spots);
  e.occlusion_fraction = s.number("occlusion_fraction", e.occlusion_fraction);
  validateIn(s.where(), [&] { e.validate(); });
  return e;
}

IndenterTrack readIndenter(const cv::FileNode& node, const std::string& where) {
  const Section s(node, where, {"shape", "semi_axes", "radius", "size", "pivot", "keyframes"});
  IndenterTrack track;
  IndenterGeometry& g = track.geometry;
  validateIn(where, [&] { g.shape = IndenterGeometry::shapeFromName(s.text("shape", "ellipsoid")); });
  if (g.shape == IndenterShape::ellipsoid && s.has("semi_axes")) {
    const auto a = s.numbers("semi_axes", 3);
    g.semi_axes = {a[0], a[1], a[2]};
  }
  if (g.shape == IndenterShape::sphere) {
    const double r = s.number("radius", 6.0);
    g.semi_axes = {r, r, r};
  }
  if (g.shape == IndenterShape::plate && s.has("size")) {
    const auto a = s.numbers("size", 2);
    g.plate_width = a[0];
    g.plate_length = a[1];
  }
  validateIn(where, [&] { g.validate(); });
  if (s.has("pivot")) {
    const auto p = s.numbers("pivot", 3);
    track.pivot = {p[0], p[1], p[2]};
  }
  const cv::FileNode kf = node["keyframes"];
  if (!kf.isSeq() || kf.size() < 1) throw InputError(where + ".keyframes: expected a list of keyframes");
  Keyframe prev;
  for (size_t i = 0; i < kf.size(); ++i) {
    const std::string kw = where + ".keyframes[" + std::to_string(i) + "]";
    const Section k(kf[static_cast<int>(i)], kw, {"t", "x", "y", "depth", "yaw", "pitch", "roll"});
    if (!k.has("t")) throw InputError(kw + ".t: missing");
    Keyframe f = prev;
    f.t = k.number("t", 0);
    f.x = k.number("x", prev.x);
    f.y = k.number("y", prev.y);
    f.depth = k.number("depth", prev.depth);
    f.yaw = k.number("yaw", prev.yaw);
    f.pitch = k.number("pitch", prev.pitch);
    f.roll = k.number("roll", prev.roll);
    if (i > 0 && !(f.t > prev.t)) throw InputError(kw + ".t: must be greater than the previous keyframe's t");
    if (f.t < 0 || f.t > 3600) throw InputError(kw + ".t: must be in [0, 3600] s");
    if (std::abs(f.x) > 30 || std::abs(f.y) > 30) throw InputError(kw + ".x/y: must be within +-30 mm");
    if (f.depth > 6 || f.depth < -30) throw InputError(kw + ".depth: must be in [-30, 6] mm");
    if (std::abs(f.yaw) > 90 || std::abs(f.pitch) > 80 || std::abs(f.roll) > 80)
      throw InputError(kw + ": angles must be within yaw +-90, pitch and roll +-80 degrees");
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
    const double surface = lattice.options().marker_depth_mm - lattice.domeOffset(k.x, k.y);
    pose.translation().z() += surface - k.depth - lowestZ(tr.geometry, pose);
    poses.push_back(pose);
  }
  return poses;
}

Scenario loadScenario(const std::string& path) {
  cv::FileStorage fs = openForReading(path);
  const Section root(fs.root(), path,
                     {"name", "description", "kind", "fps", "seed", "pad", "camera", "image", "indenters", "target"});
  Scenario sc;
  sc.name = root.text("name", "");
  if (sc.name.empty()) throw InputError(path + ": name: missing");
  sc.description = root.text("description", "");
  sc.kind = root.text("kind", "touch");
  if (sc.kind != "touch" && sc.kind != "calibration")
    throw InputError(path + ": kind: must be 'touch' or 'calibration'");
  sc.fps = root.number("fps", 30);
  if (!(sc.fps >= 1 && sc.fps <= 1000)) throw InputError(path + ": fps: must be in [1, 1000]");
  const int seed = root.integer("seed", 1);
  if (seed < 0) throw InputError(path + ": seed: must be >= 0");
  sc.seed = static_cast<unsigned>(seed);
  sc.pad = readPad(Section(fs["pad"], path + ": pad",
                           {"rows", "cols", "square_mm", "thickness_mm", "marker_depth_mm", "dome_radius_mm",
                            "nodes_per_square", "margin_squares", "friction"}));
  sc.camera = readCamera(Section(fs["camera"], path + ": camera",
                                 {"view_width", "view_height", "focal_px", "distance_mm", "baseline_mm", "k1", "k2",
                                  "p1", "p2", "k3", "flip_left", "flip_right"}));
  sc.image = readImage(Section(fs["image"], path + ": image",
                               {"noise_sigma", "blur_sigma", "vignetting", "exposure", "light_gradient",
                                "dust_blobs", "specular_spots", "occlusion_fraction"}));
  if (sc.isCalibration()) {
    const Section t(fs["target"], path + ": target",
                    {"rows", "cols", "square_mm", "poses", "tilt_deg", "yaw_deg", "shift_mm", "depth_min_mm",
                     "depth_max_mm"});
    CalibrationTarget& g = sc.target;
    g.rows = t.integer("rows", g.rows);
    g.cols = t.integer("cols", g.cols);
    g.square_mm = t.number("square_mm", g.square_mm);
    g.poses = t.integer("poses", g.poses);
    g.tilt_deg = t.number("tilt_deg", g.tilt_deg);
    g.yaw_deg = t.number("yaw_deg", g.yaw_deg);
    g.shift_mm = t.number("shift_mm", g.shift_mm);
    g.depth_min_mm = t.number("depth_min_mm", g.depth_min_mm);
    g.depth_max_mm = t.number("depth_max_mm", g.depth_max_mm);
    validateIn(path + ": target", [&] { MarkerPattern{g.rows, g.cols, g.square_mm}.validate(); });
    if (g.poses < 3 || g.poses > 1000) throw InputError(path + ": target.poses: must be in [3, 1000]");
    if (!(g.tilt_deg >= 0 && g.tilt_deg <= 60)) throw InputError(path + ": target.tilt_deg: must be in [0, 60]");
    if (!(g.depth_min_mm < g.depth_max_mm)) throw InputError(path + ": target.depth_min_mm: must be < depth_max_mm");
    return sc;
  }
  const cv::FileNode ind = fs["indenters"];
  if (!ind.isSeq() || ind.size() < 1) throw InputError(path + ": indenters: expected a list of at least one indenter");
  for (size_t i = 0; i < ind.size(); ++i)
    sc.indenters.push_back(readIndenter(ind[static_cast<int>(i)], path + ": indenters[" + std::to_string(i) + "]"));
  return sc;
}

}  // namespace onetip::sim
