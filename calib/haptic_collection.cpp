#include "calib/haptic_collection.hpp"

#include <chrono>
#include <cmath>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/csv_table.hpp"
#include "core/error.hpp"
#include "haptics/dataset_binary.hpp"
#include "haptics/display_grid.hpp"
#include "haptics/tactile_dataset.hpp"

namespace onetip::calib {

namespace fs = std::filesystem;
using haptics::TactileDataset;

void SimulatedRig::measure(const std::array<double, 3>& m, double* out) {
  sensor_.sense(device_.forward(m).plane, out);
}

void CollectionOptions::validate() const {
  haptics::gridAngles(step_deg);  // throws "step: ... is not in (0, 165]"
  if (out_path.empty()) throw InputError("CollectionOptions.out_path: must not be empty");
  if (max_new_rows < -1) throw InputError("CollectionOptions.max_new_rows: must be -1 (no limit) or >= 0");
  if (flush_every_rows < 1) throw InputError("CollectionOptions.flush_every_rows: must be >= 1");
  if (progressPath() == out_path) throw InputError("CollectionOptions.progress_path: must differ from out_path");
}

namespace {

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::string floatText(float v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string joined(const std::vector<std::string>& cells) {
  std::string s;
  for (size_t i = 0; i < cells.size(); ++i) s += (i ? "," : "") + cells[i];
  return s;
}

// The rows of an earlier run's progress file, appended to `dataset`. Cuts a
// last line without its newline off the file. InputError when the file was
// made with other options or does not follow the grid.
void resumeProgress(const std::string& path, const std::string& title, const std::string& header,
                    const std::vector<std::array<double, 3>>& grid, TactileDataset& dataset) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot read the progress file");
  std::ostringstream text;
  text << in.rdbuf();
  const std::string content = text.str();
  const size_t complete = content.rfind('\n') == std::string::npos ? 0 : content.rfind('\n') + 1;
  if (complete < content.size()) fs::resize_file(path, complete);  // a write cut short
  const std::string preamble = title + "\n" + header + "\n";
  if (complete < preamble.size()) {
    if (preamble.compare(0, complete, content, 0, complete) != 0)
      throw InputError(path + ": not a progress file of this collection (remove it to start again)");
    fs::resize_file(path, 0);
    return;
  }
  if (content.compare(0, title.size() + 1, title + "\n") != 0)
    throw InputError(path + ": made with other options ('" + content.substr(0, content.find('\n')) +
                     "', this run: '" + title + "'); remove it or use the same options");
  if (content.compare(title.size() + 1, header.size() + 1, header + "\n") != 0)
    throw InputError(path + ": line 2 is not the dataset header " + header);
  std::istringstream lines(content.substr(preamble.size(), complete - preamble.size()));
  std::string line;
  std::vector<double> sensed(static_cast<size_t>(dataset.channels));
  for (size_t row = 0; std::getline(lines, line); ++row) {
    const std::string where = path + ": line " + std::to_string(row + 3);
    if (row >= grid.size()) throw InputError(where + ": more rows than configurations");
    std::vector<std::string> cells;
    std::istringstream split(line);
    for (std::string cell; std::getline(split, cell, ',');) cells.push_back(cell);
    if (cells.size() != 3 + sensed.size())
      throw InputError(where + ": has " + std::to_string(cells.size()) + " values, expected " +
                       std::to_string(3 + sensed.size()));
    std::array<double, 3> m{};
    for (size_t c = 0; c < 3; ++c) {
      m[c] = parseNumber(cells[c], where);
      if (static_cast<float>(m[c]) != static_cast<float>(grid[row][c]))
        throw InputError(where + ": motor angles differ from configuration " + std::to_string(row) + " of the grid");
    }
    for (size_t c = 0; c < sensed.size(); ++c) sensed[c] = parseNumber(cells[3 + c], where);
    dataset.append(m, sensed);
  }
}

std::string progressLine(const TactileDataset& d, size_t row) {
  std::string line;
  for (size_t c = 0; c < 3; ++c) line += (c ? "," : "") + floatText(d.command(row)[c]);
  for (int c = 0; c < d.channels; ++c) line += "," + floatText(d.sensedRow(row)[c]);
  return line + "\n";
}

}  // namespace

CollectionResult collectDataset(CollectionRig& rig, const CollectionOptions& options, const std::atomic<bool>* stop,
                                const std::function<void(const CollectionProgress&)>& progress) {
  options.validate();
  const bool binary = endsWith(options.out_path, ".bin");
  if (!binary && !endsWith(options.out_path, ".csv"))
    throw InputError("out: '" + options.out_path + "' must end in .csv or .bin");
  const auto grid = haptics::gridConfigurations(options.step_deg);
  const int channels = rig.channels();
  if (channels < 1) throw InputError("collection: the sensor reports no channels");
  const std::string title = "# onetip collect v1 step=" + formatNumber(options.step_deg) +
                            " channels=" + std::to_string(channels) + " configurations=" + std::to_string(grid.size());
  const std::string header = joined(haptics::datasetCsvHeader(channels, true));
  const std::string progress_path = options.progressPath();

  TactileDataset dataset;
  dataset.channels = channels;
  if (fs::exists(progress_path)) resumeProgress(progress_path, title, header, grid, dataset);
  std::ofstream log(progress_path, std::ios::binary | std::ios::app);
  if (!log) throw InputError(progress_path + ": cannot write the progress file");
  if (fs::file_size(progress_path) == 0) log << title << "\n" << header << "\n" << std::flush;

  CollectionResult result;
  result.total = grid.size();
  result.resumed = dataset.size();
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<double> sensed(static_cast<size_t>(channels));
  size_t unflushed = 0;
  for (size_t row = dataset.size(); row < grid.size(); ++row) {
    const bool limit = options.max_new_rows >= 0 && result.new_rows >= static_cast<size_t>(options.max_new_rows);
    if (limit || (stop && stop->load())) break;
    rig.measure(grid[row], sensed.data());
    dataset.append(grid[row], sensed);
    log << progressLine(dataset, row);
    ++result.new_rows;
    if (++unflushed >= static_cast<size_t>(options.flush_every_rows)) {
      log.flush();
      unflushed = 0;
    }
    if (!log) throw InputError(progress_path + ": write failed (disk full?)");
    if (progress)
      progress({dataset.size(), grid.size(), result.resumed,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()});
  }
  log.flush();
  if (!log) throw InputError(progress_path + ": write failed (disk full?)");
  log.close();
  result.rows = dataset.size();
  if (dataset.size() < grid.size()) {
    result.status = CollectionResult::Status::interrupted;
    return result;
  }
  if (binary)
    haptics::writeDatasetBinary(dataset, options.out_path);
  else
    haptics::writeDatasetCsv(dataset, options.out_path);
  fs::remove(progress_path);
  return result;
}

std::string formatProgressBar(const CollectionProgress& p, int width) {
  const double fraction = p.total ? static_cast<double>(p.done) / static_cast<double>(p.total) : 1.0;
  const int filled = static_cast<int>(std::lround(fraction * width));
  const double rate = p.elapsed_s > 0 ? static_cast<double>(p.done - p.resumed) / p.elapsed_s : 0.0;
  std::string eta = "--";
  if (rate > 0) {
    const long s = std::lround(static_cast<double>(p.total - p.done) / rate);
    eta = (s >= 3600 ? std::to_string(s / 3600) + "h" : "") + (s >= 60 ? std::to_string(s / 60 % 60) + "m" : "") +
          std::to_string(s % 60) + "s";
  }
  char buf[160];
  std::snprintf(buf, sizeof buf, "] %5.1f%%  %zu/%zu rows  %.0f rows/s  ETA %s", 100.0 * fraction, p.done, p.total,
                rate, eta.c_str());
  return "[" + std::string(static_cast<size_t>(filled), '#') + std::string(static_cast<size_t>(width - filled), '.') +
         buf;
}

}  // namespace onetip::calib
