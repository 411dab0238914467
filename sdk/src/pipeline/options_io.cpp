#include "pipeline/options_io.hpp"

#include <array>
#include <cmath>
#include <set>

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

class Reader {
 public:
  Reader(const cv::FileNode& root, std::string path) : root_(root), path_(std::move(path)) {}

  void real(const char* key, double& out) const {
    const cv::FileNode n = root_[key];
    if (n.empty()) return;
    if (!n.isReal() && !n.isInt()) fail(key, "must be a number");
    out = static_cast<double>(n);
  }
  void integer(const char* key, int& out) const {
    const cv::FileNode n = root_[key];
    if (n.empty()) return;
    if (!n.isInt()) fail(key, "must be an integer");
    out = static_cast<int>(n);
  }
  void flag(const char* key, bool& out) const {
    int v = out ? 1 : 0;
    integer(key, v);
    if (v != 0 && v != 1) fail(key, "must be 0 or 1");
    out = v == 1;
  }
  void six(const char* key, std::array<double, 6>& out) const {
    const cv::FileNode n = root_[key];
    if (n.empty()) return;
    if (!n.isSeq() || n.size() != 6) fail(key, "must be a list of 6 numbers [dx, dy, dz, yaw, pitch, roll]");
    for (int k = 0; k < 6; ++k) {
      const cv::FileNode e = n[k];
      if (!e.isReal() && !e.isInt()) fail(key, "must be a list of 6 numbers [dx, dy, dz, yaw, pitch, roll]");
      out[static_cast<size_t>(k)] = static_cast<double>(e);
    }
  }
  void filter(const char* key, input::FilterKind& out) const {
    const cv::FileNode n = root_[key];
    if (n.empty()) return;
    if (!n.isString()) fail(key, "must be \"none\", \"moving_average\" or \"one_euro\"");
    const std::string name = static_cast<std::string>(n);
    for (const auto& [kind, text] : kFilters)
      if (name == text) {
        out = kind;
        return;
      }
    fail(key, "'" + name + "' is not \"none\", \"moving_average\" or \"one_euro\"");
  }
  void rejectUnknownKeys() const {
    for (const cv::FileNode& n : root_)
      if (!kKeys.count(n.name())) fail(n.name(), "unknown option");
  }
  [[noreturn]] void fail(const std::string& key, const std::string& why) const {
    throw InputError(path_ + ": " + key + ": " + why);
  }

 private:
  cv::FileNode root_;
  std::string path_;
};

void writeSix(cv::FileStorage& fs, const char* key, const std::array<double, 6>& v) {
  fs << key << "[";
  for (double x : v) fs << x;
  fs << "]";
}

}  // namespace

PipelineOptions loadPipelineOptions(const std::string& path, const PipelineOptions& base) {
  cv::FileStorage fs = openForReading(path);
  const cv::FileNode root = fs.root();
  if (!root.isMap()) throw InputError(path + ": expected a map of options");
  Reader r(root, path);
  r.rejectUnknownKeys();
  PipelineOptions o = base;
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
  try {
    o.validate();
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
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
