#include "pipeline/options_io.hpp"

#include <algorithm>
#include <array>
#include <set>
#include <vector>

#include "core/config_file.hpp"
#include "core/error.hpp"
#include "core/filestorage_io.hpp"

namespace onetip::pipeline {
namespace {

const std::set<std::string> kKeys{
    "queue_capacity", "lossless",       "playback_rate", "event_queue_capacity", "frame_queue_capacity",
    "timing_window",  "max_consecutive_source_errors",   "stop_timeout_ms",      "min_markers",
    "working_range",  "clamp_factor",   "press_mm",      "release_mm",           "gain",
    "dead_zone",      "filter",         "filter_window", "filter_min_cutoff_hz", "filter_beta",
    "filter_derivative_cutoff_hz"};

const std::array<std::pair<input::FilterKind, const char*>, 3> kFilters{
    {{input::FilterKind::none, "none"}, {input::FilterKind::moving_average, "moving_average"},
     {input::FilterKind::one_euro, "one_euro"}}};

// Reads one key at a time into `options` and validates right after each, so a
// value the options refuse is reported at its own key and line (the base
// options are valid, so the first failure belongs to the key just read).
class Reader {
 public:
  Reader(const ConfigNode& root, PipelineOptions& options) : root_(root), options_(options) {}

  void real(const char* key, double& out) const {
    const ConfigNode n = root_[key];
    if (!n.present()) return;
    out = n.real(-kLimit, kLimit);
    check(n);
  }
  void integer(const char* key, int& out) const {
    const ConfigNode n = root_[key];
    if (!n.present()) return;
    out = n.integer(-static_cast<int>(kLimit), static_cast<int>(kLimit));
    check(n);
  }
  void flag(const char* key, bool& out) const {
    const ConfigNode n = root_[key];
    if (!n.present()) return;
    out = n.flag();
    check(n);
  }
  void six(const char* key, std::array<double, 6>& out) const {
    const ConfigNode n = root_[key];
    if (!n.present()) return;
    const std::vector<double> v = n.reals(6, -kLimit, kLimit);
    std::copy(v.begin(), v.end(), out.begin());
    check(n);
  }
  void filter(const char* key, input::FilterKind& out) const {
    const ConfigNode n = root_[key];
    if (!n.present()) return;
    const std::string name = n.text();
    for (const auto& [kind, text] : kFilters)
      if (name == text) {
        out = kind;
        return check(n);
      }
    n.fail("expected \"none\", \"moving_average\" or \"one_euro\", got \"" + name + "\"");
  }

 private:
  static constexpr double kLimit = 1e9;  // beyond any option's range: the options' own checks say more
  void check(const ConfigNode& n) const {
    try {
      options_.validate();
    } catch (const InputError& e) {
      n.fail(e.what());
    }
  }
  ConfigNode root_;
  PipelineOptions& options_;
};

void writeSix(cv::FileStorage& fs, const char* key, const std::array<double, 6>& v) {
  fs << key << "[";
  for (double x : v) fs << x;
  fs << "]";
}

}  // namespace

PipelineOptions loadPipelineOptions(const std::string& path, const PipelineOptions& base) {
  const ConfigNode root = ConfigNode::load(path);
  root.allowOnly(kKeys);
  PipelineOptions o = base;
  o.validate();
  const Reader r(root, o);
  input::PoseTrackerOptions& pose = o.processor.pose;
  r.integer("queue_capacity", o.queue_capacity);
  r.flag("lossless", o.lossless);
  r.real("playback_rate", o.playback_rate);
  r.integer("event_queue_capacity", o.event_queue_capacity);
  r.integer("frame_queue_capacity", o.frame_queue_capacity);
  r.integer("timing_window", o.timing_window);
  r.integer("max_consecutive_source_errors", o.max_consecutive_source_errors);
  r.integer("stop_timeout_ms", o.stop_timeout_ms);
  r.integer("min_markers", o.processor.min_markers);
  r.six("working_range", pose.working_range);
  r.real("clamp_factor", pose.clamp_factor);
  r.real("press_mm", pose.press.press_mm);
  r.real("release_mm", pose.press.release_mm);
  r.six("gain", pose.shaping.gain);
  r.six("dead_zone", pose.shaping.dead_zone);
  r.filter("filter", pose.filter.kind);
  r.integer("filter_window", pose.filter.window);
  r.real("filter_min_cutoff_hz", pose.filter.min_cutoff_hz);
  r.real("filter_beta", pose.filter.beta);
  r.real("filter_derivative_cutoff_hz", pose.filter.derivative_cutoff_hz);
  return o;
}

void savePipelineOptions(const PipelineOptions& o, const std::string& path) {
  o.validate();
  const input::PoseTrackerOptions& pose = o.processor.pose;
  YamlWriter w;
  cv::FileStorage& fs = w.fs();
  fs << "queue_capacity" << o.queue_capacity << "lossless" << (o.lossless ? 1 : 0) << "playback_rate"
     << o.playback_rate << "event_queue_capacity" << o.event_queue_capacity << "frame_queue_capacity"
     << o.frame_queue_capacity << "timing_window" << o.timing_window << "max_consecutive_source_errors"
     << o.max_consecutive_source_errors << "stop_timeout_ms" << o.stop_timeout_ms << "min_markers"
     << o.processor.min_markers;
  writeSix(fs, "working_range", pose.working_range);
  fs << "clamp_factor" << pose.clamp_factor << "press_mm" << pose.press.press_mm << "release_mm"
     << pose.press.release_mm;
  writeSix(fs, "gain", pose.shaping.gain);
  writeSix(fs, "dead_zone", pose.shaping.dead_zone);
  const char* filter = "none";
  for (const auto& [kind, text] : kFilters)
    if (kind == pose.filter.kind) filter = text;
  fs << "filter" << filter << "filter_window" << pose.filter.window << "filter_min_cutoff_hz"
     << pose.filter.min_cutoff_hz << "filter_beta" << pose.filter.beta << "filter_derivative_cutoff_hz"
     << pose.filter.derivative_cutoff_hz;
  w.save(path);
}

}  // namespace onetip::pipeline
