#include "core/csv_table.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace onetip {

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& header)
    : file_(path), columns_(header.size()) {
  row(header);
}

void CsvWriter::row(const std::vector<std::string>& cells) {
  if (cells.size() != columns_)
    throw std::logic_error("CsvWriter: row has " + std::to_string(cells.size()) + " cells, header " +
                           std::to_string(columns_));
  auto& out = file_.stream();
  for (size_t i = 0; i < cells.size(); ++i) {
    if (i) out << ',';
    out << cells[i];
  }
  out << '\n';
}

std::string formatNumber(double v, int decimals) {
  if (!std::isfinite(v)) return "nan";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s(buf);
  if (s.find('.') != std::string::npos) {
    while (!s.empty() && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

size_t CsvTable::column(const std::string& name, const std::string& where) const {
  for (size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return i;
  throw InputError(where + ": missing column '" + name + "'");
}

namespace {
std::vector<std::string> splitLine(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream ss(line);
  while (std::getline(ss, cell, ',')) {
    while (!cell.empty() && (cell.back() == '\r' || cell.back() == ' ')) cell.pop_back();
    size_t start = cell.find_first_not_of(' ');
    cells.push_back(start == std::string::npos ? std::string() : cell.substr(start));
  }
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}
}  // namespace

CsvTable readCsv(const std::string& path) {
  requireInputFile(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open");
  std::stringstream text;
  text << in.rdbuf();
  return parseCsv(text.str(), path);
}

CsvTable parseCsv(const std::string& text, const std::string& where) {
  std::istringstream in(text);
  CsvTable t;
  std::string line;
  size_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    auto cells = splitLine(line);
    if (t.header.empty()) {
      t.header = std::move(cells);
      continue;
    }
    if (cells.size() != t.header.size())
      throw InputError(where + ": line " + std::to_string(line_no) + ": expected " +
                       std::to_string(t.header.size()) + " cells, found " +
                       std::to_string(cells.size()));
    t.rows.push_back(std::move(cells));
  }
  if (t.header.empty()) throw InputError(where + ": empty file (no header line)");
  return t;
}

double parseNumber(const std::string& cell, const std::string& where) {
  char* end = nullptr;
  const double v = std::strtod(cell.c_str(), &end);
  if (cell.empty() || end != cell.c_str() + cell.size() || !std::isfinite(v))
    throw InputError(where + ": '" + cell + "' is not a finite number");
  return v;
}

}  // namespace onetip
