// `onetip process` writes the pose uncertainty (CONVENTIONS.md: pose.csv's
// sd_dx .. sd_roll after the nine columns of the 6-D input): its header is
// the contract's, and every row holds the FrameResult::sd the public C++ API
// (onetip::Sensor, lossless) gives for the same frame of the same scenario,
// zero out of contact; in contact each component is a positive deviation.
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <memory>

#include "core/csv_table.hpp"
#include "onetip/onetip.hpp"
#include "scratch_dir.hpp"
#include "test_paths.hpp"

namespace onetip {
namespace {

const std::string kScenario = std::string(onetip::test::sourceDir()) + "/samples/scenarios/press.yaml";
const std::vector<std::string> kHeader{"frame", "contact", "state", "dx",    "dy",     "dz",       "yaw",    "pitch",
                                       "roll",  "sd_dx",   "sd_dy", "sd_dz", "sd_yaw", "sd_pitch", "sd_roll"};

// pose.csv of `onetip process` and the C++ API's results, frame by frame, for the scenario.
class ProcessUncertainty : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<test_support::ScratchDir>("onetip-process-sd");
    const std::string cmd = std::string(onetip::test::cliPath()) + " process --quiet --input sim:" + kScenario +
                            " --out " + dir_->file("pose.csv");
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    pose_ = readCsv(dir_->file("pose.csv"));

    SensorOptions options;
    options.lossless = true;
    Sensor sensor(SensorConfig("sim:" + kScenario, "", "", ""), options);
    sensor.onFrame([](const FrameResult& f) { results_[f.frame] = f; });
    sensor.start();
    ASSERT_TRUE(sensor.waitFinished(240));
  }
  static void TearDownTestSuite() { dir_.reset(); }

  static double cell(const std::vector<std::string>& row, const std::string& column) {
    return parseNumber(row[pose_.column(column, "pose.csv")], column);
  }

  static std::unique_ptr<test_support::ScratchDir> dir_;
  static CsvTable pose_;
  static std::map<std::int64_t, FrameResult> results_;
};
std::unique_ptr<test_support::ScratchDir> ProcessUncertainty::dir_;
CsvTable ProcessUncertainty::pose_;
std::map<std::int64_t, FrameResult> ProcessUncertainty::results_;

TEST_F(ProcessUncertainty, PoseCsvHoldsTheSdOfTheSameFrameFromTheCppApi) {
  EXPECT_EQ(pose_.header, kHeader);
  ASSERT_GT(pose_.rows.size(), 60u);
  int contact_rows = 0;
  for (const auto& row : pose_.rows) {
    const auto frame = static_cast<std::int64_t>(cell(row, "frame"));
    SCOPED_TRACE("frame " + std::to_string(frame));
    ASSERT_TRUE(results_.count(frame));
    const FrameResult& r = results_[frame];
    ASSERT_EQ(row[1], r.contact ? "1" : "0");
    contact_rows += r.contact;
    const auto raw = r.raw.asArray(), sd = r.sd.asArray();
    for (size_t k = 0; k < 6; ++k) {
      EXPECT_NEAR(cell(row, kHeader[3 + k]), raw[k], 1e-6) << kHeader[3 + k];
      EXPECT_NEAR(cell(row, kHeader[9 + k]), sd[k], 1e-6) << kHeader[9 + k];
      if (!r.contact) {
        EXPECT_EQ(cell(row, kHeader[9 + k]), 0.0) << kHeader[9 + k] << " out of contact";
      }
    }
  }
  EXPECT_GT(contact_rows, 20) << "the scenario must press the pad";
}

// Every contact frame after the onset has a positive sd on every axis (at
// the onset the input is zero by definition, exactly: its sd is 0).
TEST_F(ProcessUncertainty, EveryComponentHasAPositiveSdInContact) {
  int contact_rows = 0;
  bool was_in_contact = false;
  for (const auto& row : pose_.rows) {
    const bool onset = row[1] == "1" && !was_in_contact;
    was_in_contact = row[1] == "1";
    if (!was_in_contact || onset) continue;
    ++contact_rows;
    for (size_t k = 9; k < 15; ++k) EXPECT_GT(cell(row, kHeader[k]), 0.0) << "frame " << row[0] << " " << kHeader[k];
  }
  EXPECT_GT(contact_rows, 20);
}

}  // namespace
}  // namespace onetip
