#include "pipeline/options_io.hpp"

#include <set>
#include <type_traits>
#include <vector>

#include "core/config_file.hpp"
#include "core/error.hpp"
#include "core/filestorage_io.hpp"
#include "core/option_table.hpp"

namespace onetip::pipeline {
namespace {

// Calls fn(option, setting) for every option and the pipeline setting it feeds.
// S and P are SensorOptions and PipelineOptions, either of them const.
template <typename S, typename P, typename Fn>
void forEachPipelineField(S& s, P& p, Fn&& fn) {
  auto& pose = p.processor.pose;
  fn(s.queue_capacity, p.queue_capacity);
  fn(s.lossless, p.lossless);
  fn(s.playback_rate, p.playback_rate);
  fn(s.event_queue_capacity, p.event_queue_capacity);
  fn(s.frame_queue_capacity, p.frame_queue_capacity);
  fn(s.timing_window, p.timing_window);
  fn(s.max_consecutive_source_errors, p.max_consecutive_source_errors);
  fn(s.stop_timeout_ms, p.stop_timeout_ms);
  fn(s.min_markers, p.processor.min_markers);
  fn(s.working_range, pose.working_range);
  fn(s.clamp_factor, pose.clamp_factor);
  fn(s.press_mm, pose.press.press_mm);
  fn(s.release_mm, pose.press.release_mm);
  fn(s.gain, pose.shaping.gain);
  fn(s.dead_zone, pose.shaping.dead_zone);
  fn(s.filter, pose.filter.kind);
  fn(s.filter_window, pose.filter.window);
  fn(s.filter_min_cutoff_hz, pose.filter.min_cutoff_hz);
  fn(s.filter_beta, pose.filter.beta);
  fn(s.filter_derivative_cutoff_hz, pose.filter.derivative_cutoff_hz);
}

static_assert(static_cast<int>(input::FilterKind::none) == static_cast<int>(FilterKind::none) &&
              static_cast<int>(input::FilterKind::moving_average) == static_cast<int>(FilterKind::moving_average) &&
              static_cast<int>(input::FilterKind::one_euro) == static_cast<int>(FilterKind::one_euro));

template <typename To, typename From>
void copyValue(To& to, const From& from) {
  if constexpr (std::is_enum_v<To>)
    to = static_cast<To>(static_cast<int>(from));
  else
    to = from;
}

// The values of a present key, of the row's type and inside its range (the
// messages of config_file.hpp, naming the file, line and key).
std::vector<double> readKey(const ConfigNode& n, const OptionInfo& row) {
  switch (row.type) {
    case OptionType::integer:
      return {static_cast<double>(n.integer(static_cast<int>(row.min), static_cast<int>(row.max)))};
    case OptionType::real:
      return {n.real(row.min, row.max)};
    case OptionType::flag:
      return {n.flag() ? 1.0 : 0.0};
    case OptionType::axes:
      return n.reals(6, row.min, row.max);
    case OptionType::choice:
      break;
  }
  const std::string text = n.text();
  std::string expected;
  for (std::size_t c = 0; c < row.choices.size(); ++c) {
    if (text == row.choices[c]) return {static_cast<double>(c)};
    expected += (c == 0 ? "\"" : c + 1 == row.choices.size() ? " or \"" : ", \"") + std::string(row.choices[c]) + "\"";
  }
  n.fail("expected " + expected + ", got \"" + text + "\"");
}

void writeKey(cv::FileStorage& fs, const OptionInfo& row, std::size_t option, const SensorOptions& o) {
  const double v = option_table::get(o, option, 0);
  fs << row.name;
  switch (row.type) {
    case OptionType::integer:
    case OptionType::flag:
      fs << static_cast<int>(v);
      return;
    case OptionType::real:
      fs << v;
      return;
    case OptionType::choice:
      fs << row.choices[static_cast<std::size_t>(v)];
      return;
    case OptionType::axes:
      fs << "[";
      for (int k = 0; k < 6; ++k) fs << option_table::get(o, option, k);
      fs << "]";
      return;
  }
}

}  // namespace

PipelineOptions toPipelineOptions(const SensorOptions& o, const PipelineOptions& base) {
  PipelineOptions p = base;
  forEachPipelineField(o, p, [](const auto& option, auto& setting) { copyValue(setting, option); });
  return p;
}

SensorOptions toSensorOptions(const PipelineOptions& p) {
  SensorOptions o;
  forEachPipelineField(o, p, [](auto& option, const auto& setting) { copyValue(option, setting); });
  return o;
}

SensorOptions loadSensorOptions(const std::string& path, const SensorOptions& base) {
  const ConfigNode root = ConfigNode::load(path);
  const std::span<const OptionInfo> rows = option_table::rows();
  std::set<std::string> keys;
  for (const OptionInfo& row : rows) keys.insert(row.name);
  root.allowOnly(keys);
  option_table::validate(base);
  SensorOptions o = base;
  // Table order, each key validated right after it is read, so a relation the
  // options refuse is reported at the key that broke it (the base is valid).
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const ConfigNode n = root[rows[i].name];
    if (!n.present()) continue;
    const std::vector<double> values = readKey(n, rows[i]);
    try {
      for (std::size_t k = 0; k < values.size(); ++k) option_table::set(o, i, static_cast<int>(k), values[k]);
      option_table::validate(o);
    } catch (const InputError& e) {
      n.fail(e.what());
    }
  }
  return o;
}

void saveSensorOptions(const SensorOptions& o, const std::string& path) {
  option_table::validate(o);
  YamlWriter w;
  const std::span<const OptionInfo> rows = option_table::rows();
  for (std::size_t i = 0; i < rows.size(); ++i) writeKey(w.fs(), rows[i], i, o);
  w.save(path);
}

PipelineOptions loadPipelineOptions(const std::string& path, const PipelineOptions& base) {
  return toPipelineOptions(loadSensorOptions(path, toSensorOptions(base)), base);
}

}  // namespace onetip::pipeline
