// Calibration and pattern files: round trips, the shipped reference file, and
// the errors bad files must give (one line naming the bad key, no partial file).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/atomic_file.hpp"
#include "core/calibration.hpp"
#include "core/csv_table.hpp"
#include "core/error.hpp"
#include "core/pattern.hpp"
#include "scratch_dir.hpp"
#include "input_error_of.hpp"
#include "test_paths.hpp"

using namespace onetip;
namespace fs = std::filesystem;
using onetip::test_support::inputErrorOf;

namespace {
void writeText(const fs::path& p, const std::string& s) { std::ofstream(p) << s; }
std::string readText(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
}  // namespace

TEST(Files, ReadsTheReferenceCalibrationOfTheRealPhotos) {
  const std::string path = std::string(onetip::test::testDataDir()) +
                           "/real/opencv_stereo_9x6/reference/reference_calib_sbs_pairs01-09.yaml";
  const StereoCalibration c = loadCalibration(path);
  EXPECT_EQ(c.image_width, 1280);
  EXPECT_EQ(c.split_x, 640);
  EXPECT_NEAR(c.K_left(0, 0), 533.72, 0.01);
  EXPECT_NEAR(c.D_right[0], -0.3096, 1e-4);
  EXPECT_NEAR(c.T[0], -83.1688, 1e-3);
}

TEST(Files, CalibrationRoundTrip) {
  const test_support::ScratchDir scratch("onetip-core-files");
  StereoCalibration c;
  c.image_width = 1920;
  c.image_height = 1080;
  c.split_x = 960;
  c.flip_right = true;
  c.K_left = cv::Matx33d(1000, 0, 479.5, 0, 1001, 539.5, 0, 0, 1);
  c.K_right = c.K_left;
  c.D_left = {-0.1, 0.02, 0.001, -0.002, 0.003};
  c.T = {-24, 0.1, 0.2};
  const auto p = (scratch.path() / "calib.yaml").string();
  saveCalibration(c, p, 0.123);
  const StereoCalibration d = loadCalibration(p);
  EXPECT_EQ(d.flip_right, true);
  EXPECT_EQ(d.flip_left, false);
  EXPECT_DOUBLE_EQ(d.K_left(1, 1), 1001);
  EXPECT_DOUBLE_EQ(d.D_left[4], 0.003);
  EXPECT_DOUBLE_EQ(d.T[2], 0.2);
}

TEST(Files, BadCalibrationNamesTheKey) {
  const test_support::ScratchDir scratch("onetip-core-files");
  const auto dir = scratch.path();
  EXPECT_NE(inputErrorOf([&] { loadCalibration((dir / "missing.yaml").string()); }).find("no such file"),
            std::string::npos);
  // a folder where the file belongs is named as a directory, not as missing
  EXPECT_EQ(inputErrorOf([&] { loadCalibration(dir.string()); }), dir.string() + ": is a directory, not a file");
  EXPECT_EQ(inputErrorOf([&] { readCsv(dir.string()); }), dir.string() + ": is a directory, not a file");
  writeText(dir / "nok.yaml", "%YAML:1.0\n---\nimage_width: 100\nimage_height: 50\nsplit_x: 50\n");
  EXPECT_NE(inputErrorOf([&] { loadCalibration((dir / "nok.yaml").string()); }).find("flip_left"),
            std::string::npos);
  writeText(dir / "garbage.yaml", "%YAML:1.0\n---\n: : [\n");
  EXPECT_NE(inputErrorOf([&] { loadCalibration((dir / "garbage.yaml").string()); }), "");
}

TEST(Files, PatternRoundTripAndValidation) {
  const test_support::ScratchDir scratch("onetip-core-files");
  const auto p = (scratch.path() / "pattern.yaml").string();
  savePattern({9, 13, 2.5}, p);
  const MarkerPattern q = loadPattern(p);
  EXPECT_EQ(q.rows, 9);
  EXPECT_EQ(q.cols, 13);
  EXPECT_DOUBLE_EQ(q.square_mm, 2.5);
  writeText(scratch.path() / "bad_pattern.yaml", "%YAML:1.0\n---\nrows: 0\ncols: 5\nsquare_mm: 1\n");
  EXPECT_NE(inputErrorOf([&] { loadPattern((scratch.path() / "bad_pattern.yaml").string()); }).find("rows"),
            std::string::npos);
}

// marker_depth_mm is optional: a file of the three documented keys reads the
// default, a pad with another depth writes and reads it back, and a bad depth
// is named with its file, line and key.
TEST(Files, PatternMarkerDepthIsOptionalAndChecked) {
  const test_support::ScratchDir scratch("onetip-core-files");
  const auto three = scratch.path() / "three_keys.yaml";
  writeText(three, "%YAML:1.0\n---\nrows: 5\ncols: 6\nsquare_mm: 1.5\n");
  EXPECT_DOUBLE_EQ(loadPattern(three.string()).marker_depth_mm, MarkerPattern{}.marker_depth_mm);
  const auto deep = (scratch.path() / "deep.yaml").string();
  MarkerPattern pad{5, 6, 1.5};
  pad.marker_depth_mm = 0.55;
  savePattern(pad, deep);
  EXPECT_DOUBLE_EQ(loadPattern(deep).marker_depth_mm, 0.55);
  const auto plain = (scratch.path() / "plain.yaml").string();
  savePattern({5, 6, 1.5}, plain);
  EXPECT_EQ(readText(plain).find("marker_depth_mm"), std::string::npos);  // the documented three keys only
  const auto bad = scratch.path() / "bad_depth.yaml";
  writeText(bad, "%YAML:1.0\n---\nrows: 5\ncols: 6\nsquare_mm: 1.5\nmarker_depth_mm: -1\n");
  const std::string why = inputErrorOf([&] { loadPattern(bad.string()); });
  EXPECT_NE(why.find("bad_depth.yaml:6"), std::string::npos) << why;
  EXPECT_NE(why.find("marker_depth_mm"), std::string::npos) << why;
}

TEST(Files, AtomicFileLeavesNothingWithoutCommit) {
  const test_support::ScratchDir scratch("onetip-core-files");
  const auto p = scratch.path() / "out.csv";
  fs::remove(p);
  {
    CsvWriter w(p.string(), {"a", "b"});
    w.row({"1", "2"});
  }
  EXPECT_FALSE(fs::exists(p));
  {
    CsvWriter w(p.string(), {"a", "b"});
    w.row({"1", formatNumber(2.5)});
    w.commit();
  }
  const CsvTable t = readCsv(p.string());
  ASSERT_EQ(t.rows.size(), 1u);
  EXPECT_EQ(t.rows[0][1], "2.5");
  for (const auto& e : fs::directory_iterator(scratch.path()))
    EXPECT_EQ(e.path().string().find(".tmp."), std::string::npos) << e.path();
}
