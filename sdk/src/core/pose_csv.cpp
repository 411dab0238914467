#include "core/pose_csv.hpp"

#include "core/csv_table.hpp"

namespace onetip {
namespace {

constexpr const char* kAxes[6] = {"dx", "dy", "dz", "yaw", "pitch", "roll"};

void appendNumbers(std::vector<std::string>& row, const Input6& v) {
  for (double x : v.asArray()) row.push_back(formatNumber(x));
}

}  // namespace

std::vector<std::string> poseCsvHeader(bool with_sd) {
  std::vector<std::string> h{"frame", "contact", "state"};
  for (const char* a : kAxes) h.emplace_back(a);
  if (with_sd)
    for (const char* a : kAxes) h.push_back(std::string("sd_") + a);
  return h;
}

std::vector<std::string> poseCsvRow(std::int64_t frame, bool contact, ContactState state, const Input6& v) {
  std::vector<std::string> row{std::to_string(frame), contact ? "1" : "0",
                               std::string(toString(contact ? state : ContactState::none))};
  appendNumbers(row, v);
  return row;
}

std::vector<std::string> poseCsvRow(std::int64_t frame, bool contact, ContactState state, const Input6& v,
                                    const Input6& sd) {
  std::vector<std::string> row = poseCsvRow(frame, contact, state, v);
  appendNumbers(row, sd);
  return row;
}

}  // namespace onetip
