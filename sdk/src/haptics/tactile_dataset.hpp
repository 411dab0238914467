// haptics/tactile_dataset.hpp — the renderer's data set: pairs (s, m) of a
// sensed vector s in R^N and the motor command m in R^3 that produced it.
//
// m = (m1, m2, m3) are servo angles in degrees (m1 the front motor, m2 and m3
// the two rear motors, see platform_kinematics.hpp). s is whatever the sensor
// reports, in its own units (BioTac-like counts, or mm for the onetip contact
// field feature). Rows are stored row-major as float: commands 3 per row,
// sensed N per row.
//
// CSV (docs/reference.md): a dataset has header `m1,m2,m3,s1,...,sN`, a queries
// file `s1,...,sN`. Readers refuse a wrong header, more than kMaxDatasetChannels
// channels, a cell that is not a finite float32 (NaN, inf, or beyond +-3.4e38
// such as 1e39, which would become inf when stored) or an empty file with an
// InputError naming the file, line and column.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace onetip::haptics {

// The most sensed channels a dataset or queries file may have (CSV and binary
// alike). The renderer's principal-axes search space costs O(N^3) to build:
// 1,024 channels take 1.5 s and 100 MB, 4,000 took 53 s and 520 MB from a
// 55 KB file. 1,024 holds onetip's whole 17x17 marker field (867 values).
constexpr int kMaxDatasetChannels = 1024;

struct TactileDataset {
  int channels = 0;             // N
  std::vector<float> commands;  // size 3 * size(), degrees
  std::vector<float> sensed;    // size N * size()

  size_t size() const noexcept { return commands.size() / 3; }
  const float* command(size_t row) const { return commands.data() + 3 * row; }
  const float* sensedRow(size_t row) const { return sensed.data() + static_cast<size_t>(channels) * row; }
  void append(const std::array<double, 3>& m, const std::vector<double>& s);
};

// Query vectors s (N per row, row-major) without commands.
struct QuerySet {
  int channels = 0;
  std::vector<double> values;
  size_t size() const noexcept { return channels ? values.size() / static_cast<size_t>(channels) : 0; }
  const double* row(size_t i) const { return values.data() + static_cast<size_t>(channels) * i; }
};

// The CSV header of a dataset (with_commands) or a queries file with N channels.
std::vector<std::string> datasetCsvHeader(int channels, bool with_commands);

TactileDataset readDatasetCsv(const std::string& path);
QuerySet readQueriesCsv(const std::string& path);
// Writes atomically; numbers round-trip the stored floats exactly.
void writeDatasetCsv(const TactileDataset& dataset, const std::string& path);

// Reads either format, telling them apart by the binary magic.
TactileDataset loadDataset(const std::string& path);

}  // namespace onetip::haptics
