// The option table (onetip/sensor_option_table.hpp) and what is derived from
// it on the C++ side (label options): the one validation vocabulary's
// messages; keyed get/set against the struct's own fields; every option
// reaching its own pipeline setting and back; the pipeline's defaults equal
// to the table's; every row through the options file, and every row's
// out-of-range value refused in a file at its line and key; the table in
// docs/reference.md equal to the header's, row for row.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "core/option_checks.hpp"
#include "core/option_table.hpp"
#include "input_error_of.hpp"
#include "onetip/error.hpp"
#include "pipeline/options_io.hpp"
#include "scratch_dir.hpp"
#include "test_paths.hpp"

namespace onetip {
namespace {

using test_support::inputErrorOf;

// An in-range value other than the default for value k of a row.
double otherValue(const OptionInfo& row, int k) {
  const double d = row.default_value[static_cast<std::size_t>(k)];
  return d == row.max ? row.min : row.max;
}

// The options with value k of `option` changed to otherValue (release_mm to
// its minimum, to stay below press_mm).
SensorOptions withOther(std::size_t option, int k) {
  SensorOptions o;
  const OptionInfo& row = option_table::rows()[option];
  option_table::set(o, option, k, std::string(row.name) == "release_mm" ? row.min : otherValue(row, k));
  return o;
}

TEST(OptionChecks, OneMessageStyleNamingFieldRangeUnitAndValue) {
  EXPECT_EQ(inputErrorOf([] { requireInRange("options.queue_capacity", 0, 1, 64, "frames"); }),
            "options.queue_capacity: must be in [1, 64] frames, got 0");
  EXPECT_EQ(inputErrorOf([] { requireInRange("image effects: exposure", 3.5, 0.2, 3); }),
            "image effects: exposure: must be in [0.2, 3], got 3.5");
  EXPECT_EQ(inputErrorOf([] { requireInRange("f", std::nan(""), 0, 1); }), "f: must be in [0, 1], got nan");
  EXPECT_NE(inputErrorOf([] { requireInRange("f", std::numeric_limits<double>::infinity(), 0, 1e300); }), "");
  EXPECT_EQ(inputErrorOf([] { requireInRange("f", 1, 1, 1); }), "");  // closed at both ends
  EXPECT_EQ(inputErrorOf([] { requireWhole("f", 2.5); }), "f: must be a whole number, got 2.5");
  EXPECT_EQ(inputErrorOf([] { requireBelow("options.release_mm", 2, "press_mm", 1.5); }),
            "options.release_mm: must be below press_mm (1.5), got 2");
  EXPECT_EQ(inputErrorOf([] { requireAtLeast("input filter: window", 0, 1, "frames"); }),
            "input filter: window: must be at least 1 frames, got 0");
  EXPECT_EQ(inputErrorOf([] { requireAbove("press button: press_mm", 0, 0, "mm"); }),
            "press button: press_mm: must be above 0 mm, got 0");
  EXPECT_NE(inputErrorOf([] { requireAtLeast("f", std::numeric_limits<double>::infinity(), 0); }), "");
  EXPECT_EQ(inputErrorOf([] { requireFinite("f", -std::numeric_limits<double>::infinity()); }),
            "f: must be finite, got -inf");
  EXPECT_NE(inputErrorOf([] { requireBelow("f", std::nan(""), "g", 1); }), "");
  EXPECT_EQ(numberText(0.05), "0.05");
  EXPECT_EQ(numberText(600000), "600000");
  EXPECT_EQ(numberText(1e6), "1e+06");
  EXPECT_EQ(numberText(0.1 + 0.2), "0.30000000000000004");  // more digits only when needed to read it back
  EXPECT_EQ(rangeText(0.001, 1000, "Hz"), "[0.001, 1000] Hz");
}

TEST(OptionTable, ValidateNamesTheFieldItsRangeAndUnit) {
  SensorOptions o;
  EXPECT_NO_THROW(o.validate());
  o.working_range[4] = -1;
  try {
    o.validate();
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::input);
    EXPECT_STREQ(e.what(), "options.working_range[4] (pitch): must be in [0.001, 1000] deg, got -1");
  }
  o = {};
  o.release_mm = 1.5;  // == press_mm
  EXPECT_EQ(inputErrorOf([&] { option_table::validate(o); }),
            "options.release_mm: must be below press_mm (1.5), got 1.5");
  o = {};
  o.filter = static_cast<FilterKind>(7);
  EXPECT_EQ(inputErrorOf([&] { option_table::validate(o); }), "options.filter: must be in [0, 2], got 7");
}

TEST(OptionTable, KeyedAccessReadsAndWritesTheStructsOwnFields) {
  SensorOptions o;
  EXPECT_EQ(o.get("queue_capacity"), o.queue_capacity);
  EXPECT_EQ(o.get("dead_zone", 5), o.dead_zone[5]);
  o.set("gain", -2.5, 3);
  EXPECT_EQ(o.gain[3], -2.5);
  o.set("filter", 2);
  EXPECT_EQ(o.filter, FilterKind::one_euro);
  o.set("lossless", 1);
  EXPECT_TRUE(o.lossless);

  const SensorOptions before = o;
  EXPECT_THROW(o.set("queue_capacity", 65), Error);
  EXPECT_THROW(o.set("queue_capacity", 2.5), Error);  // not a whole number
  EXPECT_THROW(o.set("gain", 1, 6), Error);           // no seventh axis
  EXPECT_THROW(o.set("no_such_option", 1), Error);
  EXPECT_THROW((void)o.get("no_such_option"), Error);
  EXPECT_EQ(o, before);  // a refused set changes nothing
}

TEST(OptionTable, DefaultsAreTheStructsAndInsideTheirRanges) {
  const SensorOptions defaults;
  const auto rows = SensorOptions::table();
  ASSERT_EQ(rows.size(), 20u);
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (int k = 0; k < rows[i].count; ++k) {
      const double d = rows[i].default_value[static_cast<std::size_t>(k)];
      EXPECT_EQ(option_table::get(defaults, i, k), d) << rows[i].name << "[" << k << "]";
      EXPECT_TRUE(d >= rows[i].min && d <= rows[i].max) << rows[i].name;
    }
}

TEST(OptionTable, EveryOptionReachesItsOwnPipelineSettingAndBack) {
  // A missing line in the field map resets that option on the way back; two
  // options mapped to one setting change each other.
  const auto rows = option_table::rows();
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (int k = 0; k < rows[i].count; ++k) {
      const SensorOptions o = withOther(i, k);
      EXPECT_EQ(pipeline::toSensorOptions(pipeline::toPipelineOptions(o)), o) << rows[i].name << "[" << k << "]";
    }
}

TEST(OptionTable, ThePipelinesOwnDefaultsAreTheTables) {
  // The command-line tools start from PipelineOptions{}: it must agree with the table.
  EXPECT_EQ(pipeline::toSensorOptions(pipeline::PipelineOptions{}), SensorOptions{});
  EXPECT_NO_THROW(pipeline::PipelineOptions{}.validate());
  pipeline::PipelineOptions p;
  p.stop_timeout_ms = 5;
  EXPECT_EQ(inputErrorOf([&] { p.validate(); }), "options.stop_timeout_ms: must be in [10, 600000] ms, got 5");
}

TEST(OptionsFile, EveryRowIsWrittenAndReadBack) {
  const test_support::ScratchDir dir("onetip-options");
  const auto rows = option_table::rows();
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (int k = 0; k < rows[i].count; ++k) {
      const SensorOptions o = withOther(i, k);
      const std::string path = dir.file("o.yaml");
      pipeline::saveSensorOptions(o, path);
      EXPECT_EQ(pipeline::loadSensorOptions(path), o) << rows[i].name << "[" << k << "]";
    }
}

TEST(OptionsFile, EveryRowRefusesAValueOutsideItsRangeAtItsLineAndKey) {
  const test_support::ScratchDir dir("onetip-options");
  for (const OptionInfo& row : option_table::rows()) {
    if (row.type == OptionType::flag) continue;  // a flag file value is true/false/0/1 by type
    const std::string bad = row.type == OptionType::choice    ? "bogus"
                            : row.type == OptionType::integer ? std::to_string(static_cast<long long>(row.max) + 1)
                                                              : numberText(std::nextafter(row.max, 2 * row.max + 1));
    const std::string value = row.type == OptionType::axes ? "[1, 1, 1, 1, 1, " + bad + "]" : bad;
    const std::string path = dir.file(std::string(row.name) + ".yaml");
    std::ofstream(path) << "# options\n" << row.name << ": " << value << "\n";
    const std::string message = inputErrorOf([&] { pipeline::loadSensorOptions(path); });
    const std::string key = std::string(row.name) + (row.type == OptionType::axes ? "[5]" : "");
    EXPECT_EQ(message.rfind(path + ":2: key '" + key + "': expected ", 0), 0u) << message;
    EXPECT_NE(message.find(bad), std::string::npos) << message;
  }
}

// A row as docs/reference.md prints it: | `key` | type | `default` | [min, max] | unit | meaning |
std::string docsRow(const OptionInfo& row) {
  const char* types[] = {"integer", "real", "flag", "choice", "axes"};
  std::string type = types[static_cast<int>(row.type)], value;
  for (std::size_t c = 0; c < row.choices.size(); ++c) type += (c ? ", " : ": ") + std::string(row.choices[c]);
  const double d = row.default_value[0];
  if (row.type == OptionType::axes) {
    value = "[";
    for (int k = 0; k < 6; ++k) value += (k ? ", " : "") + numberText(row.default_value[static_cast<std::size_t>(k)]);
    value += "]";
  } else if (row.type == OptionType::flag) {
    value = d != 0 ? "true" : "false";
  } else if (row.type == OptionType::choice) {
    value = row.choices[static_cast<std::size_t>(d)];
  } else {
    value = numberText(d);
  }
  std::string unit = row.unit;
  if (const auto bar = unit.find('|'); bar != std::string::npos) unit.replace(bar, 1, ", ");
  return "| `" + std::string(row.name) + "` | " + type + " | `" + value + "` | " + rangeText(row.min, row.max) + " | " +
         unit + " | " + row.doc + " |";
}

TEST(OptionTable, TheDocsTableIsTheHeadersRowForRow) {
  std::ifstream docs(std::string(onetip::test::sourceDir()) + "/docs/reference.md");
  ASSERT_TRUE(docs.good());
  std::vector<std::string> lines;
  bool in_table = false;
  for (std::string line; std::getline(docs, line);) {
    if (line.rfind("#### The option table", 0) == 0)
      in_table = true;
    else if (in_table && line.rfind("#", 0) == 0)
      break;
    else if (in_table && line.rfind("| `", 0) == 0)
      lines.push_back(line);
  }
  const auto rows = option_table::rows();
  ASSERT_EQ(lines.size(), rows.size()) << "docs/reference.md, section \"The option table\"";
  for (std::size_t i = 0; i < rows.size(); ++i) EXPECT_EQ(lines[i], docsRow(rows[i]));
}

}  // namespace
}  // namespace onetip
