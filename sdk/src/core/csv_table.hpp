// core/csv_table.hpp — small CSV writer and reader for the files of
// docs/reference.md (pose.csv, markers.csv, gt_*.csv, datasets, timing.csv).
//
// CsvWriter writes through an AtomicFile: the file appears complete at
// commit() or not at all. Numbers are written with enough digits to round-trip
// the precision that matters (1e-6 mm, 1e-6 deg).
#pragma once

#include <string>
#include <vector>

#include "core/atomic_file.hpp"

namespace onetip {

class CsvWriter {
 public:
  CsvWriter(const std::string& path, const std::vector<std::string>& header);
  // Appends one row of already formatted cells; throws if the count differs
  // from the header.
  void row(const std::vector<std::string>& cells);
  void commit() { file_.commit(); }
  void flush() { file_.flush(); }      // AtomicFile::flush: a write error now, naming its cause
  void commitFlushed() { file_.commitFlushed(); }
  void discard() { file_.discard(); }  // AtomicFile::discard
  const std::string& path() const { return file_.path(); }

 private:
  AtomicFile file_;
  size_t columns_;
};

// "%.6f" style formatting without trailing noise for integers.
std::string formatNumber(double v, int decimals = 6);

struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  // Index of a header column; throws InputError naming the file and column.
  size_t column(const std::string& name, const std::string& where) const;
};

// Reads a comma-separated file with a header line; throws InputError on a
// missing file or a row whose cell count differs from the header's.
CsvTable readCsv(const std::string& path);
// The same for text already read; `where` names it in messages.
CsvTable parseCsv(const std::string& text, const std::string& where);

// Parses a cell as a finite double; throws InputError naming where.
double parseNumber(const std::string& cell, const std::string& where);

}  // namespace onetip
