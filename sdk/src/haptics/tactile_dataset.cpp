#include "haptics/tactile_dataset.hpp"

#include <charconv>
#include <cmath>
#include <limits>

#include "core/atomic_file.hpp"
#include "core/csv_table.hpp"
#include "core/error.hpp"
#include "haptics/dataset_binary.hpp"

namespace onetip::haptics {

void TactileDataset::append(const std::array<double, 3>& m, const std::vector<double>& s) {
  if (static_cast<int>(s.size()) != channels)
    throw InputError("dataset row has " + std::to_string(s.size()) + " channels, expected " +
                     std::to_string(channels));
  for (double v : m) commands.push_back(static_cast<float>(v));
  for (double v : s) sensed.push_back(static_cast<float>(v));
}

std::vector<std::string> datasetCsvHeader(int channels, bool with_commands) {
  std::vector<std::string> header;
  if (with_commands) header = {"m1", "m2", "m3"};
  for (int i = 1; i <= channels; ++i) header.push_back("s" + std::to_string(i));
  return header;
}

namespace {

// Checks the header against datasetCsvHeader and returns N.
int channelsFromHeader(const CsvTable& t, bool with_commands, const std::string& path) {
  const size_t fixed = with_commands ? 3 : 0;
  if (t.header.size() <= fixed)
    throw InputError(path + ": header has no sensed channels (expected " +
                     (with_commands ? std::string("m1,m2,m3,") : std::string()) + "s1,...,sN)");
  if (t.header.size() - fixed > static_cast<size_t>(kMaxDatasetChannels))
    throw InputError(path + ": line 1: " + std::to_string(t.header.size() - fixed) + " sensed channels, more than " +
                     std::to_string(kMaxDatasetChannels));
  const int channels = static_cast<int>(t.header.size() - fixed);
  const auto expected = datasetCsvHeader(channels, with_commands);
  for (size_t i = 0; i < expected.size(); ++i)
    if (t.header[i] != expected[i])
      throw InputError(path + ": header column " + std::to_string(i + 1) + " is '" + t.header[i] +
                       "', expected '" + expected[i] + "'");
  if (t.rows.empty()) throw InputError(path + ": no data rows");
  return channels;
}

std::string cellWhere(const std::string& path, size_t row, const std::string& column) {
  return path + ": line " + std::to_string(row + 2) + ", column " + column;
}

// A cell as a finite number that float32 can hold.
double parseFloatCell(const std::string& cell, const std::string& where) {
  const double v = parseNumber(cell, where);
  if (std::fabs(v) > static_cast<double>(std::numeric_limits<float>::max()))
    throw InputError(where + ": '" + cell + "' is beyond the float32 range (+-3.4e38)");
  return v;
}

std::string shortestFloat(float v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

}  // namespace

TactileDataset readDatasetCsv(const std::string& path) {
  const CsvTable t = readCsv(path);
  TactileDataset d;
  d.channels = channelsFromHeader(t, true, path);
  d.commands.reserve(3 * t.rows.size());
  d.sensed.reserve(static_cast<size_t>(d.channels) * t.rows.size());
  for (size_t r = 0; r < t.rows.size(); ++r)
    for (size_t c = 0; c < t.header.size(); ++c) {
      const float v = static_cast<float>(parseFloatCell(t.rows[r][c], cellWhere(path, r, t.header[c])));
      (c < 3 ? d.commands : d.sensed).push_back(v);
    }
  return d;
}

QuerySet readQueriesCsv(const std::string& path) {
  const CsvTable t = readCsv(path);
  QuerySet q;
  q.channels = channelsFromHeader(t, false, path);
  q.values.reserve(static_cast<size_t>(q.channels) * t.rows.size());
  for (size_t r = 0; r < t.rows.size(); ++r)
    for (size_t c = 0; c < t.header.size(); ++c)
      q.values.push_back(parseFloatCell(t.rows[r][c], cellWhere(path, r, t.header[c])));
  return q;
}

void writeDatasetCsv(const TactileDataset& dataset, const std::string& path) {
  CsvWriter out(path, datasetCsvHeader(dataset.channels, true));
  std::vector<std::string> cells(3 + static_cast<size_t>(dataset.channels));
  for (size_t r = 0; r < dataset.size(); ++r) {
    for (size_t c = 0; c < 3; ++c) cells[c] = shortestFloat(dataset.command(r)[c]);
    for (int c = 0; c < dataset.channels; ++c) cells[3 + static_cast<size_t>(c)] = shortestFloat(dataset.sensedRow(r)[c]);
    out.row(cells);
  }
  out.commit();
}

TactileDataset loadDataset(const std::string& path) {
  requireInputFile(path);
  return isBinaryDataset(path) ? readDatasetBinary(path) : readDatasetCsv(path);
}

}  // namespace onetip::haptics
