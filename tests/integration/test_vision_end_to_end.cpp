// The vision front end end to end (issue 3 acceptance): rendered simulator
// frames at the default noise -> corners -> ids -> triangulation -> S, against
// the simulator's exact markers; the same with the calibration that
// `onetip calibrate` makes from the simulated calibration scene; ids kept under
// occlusion; real photos through `onetip process`; bad frames skipped.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "core/csv_table.hpp"
#include "pipeline/frame_processor.hpp"
#include "sim/ground_truth_writer.hpp"
#include "sim/simulator.hpp"
#include "scratch_dir.hpp"
#include "test_paths.hpp"
#include "sanitizer_leg.hpp"

using namespace onetip;
namespace fs = std::filesystem;

namespace {
const fs::path kSource(onetip::test::sourceDir());
const fs::path kReal = fs::path(onetip::test::testDataDir()) / "real" / "opencv_stereo_9x6";

int run(const std::string& cmd) { return std::system((cmd + " >/dev/null 2>&1").c_str()); }

struct MarkerErrors {
  double sum_sq = 0, max = 0;
  long n = 0, expected = 0;
  double rms() const { return std::sqrt(sum_sq / std::max(1L, n)); }
};

// Plays a scenario through the FrameProcessor and compares every triangulated
// marker (S) with the simulator's exact one. `occlude_after` > 0 renders frames
// from that index with a dark band over 20% of the pad (the rest frame is clean).
MarkerErrors playScenario(const std::string& name, const StereoCalibration& calib, int frames, int occlude_after = 0) {
  sim::Scenario sc = sim::loadScenario((kSource / "samples" / "scenarios" / (name + ".yaml")).string());
  sim::SimulatorOptions o;
  o.frames = frames;
  sim::Simulator sim(sc, o);
  pipeline::FrameProcessor processor(calib, sim.pattern());
  MarkerErrors e;
  while (!sim.done()) {
    const sim::GroundTruthFrame& f = sim.next();
    if (occlude_after > 0 && f.index == occlude_after) {
      sim::ImageEffects occluded = sc.image;
      occluded.occlusion_fraction = 0.2;
      sim.setImageEffects(occluded);
    }
    const cv::Mat frame = sim.render();
    const pipeline::FrameResult r = processor.process(frame, f.t);
    EXPECT_TRUE(r.status == pipeline::FrameStatus::ok || r.status == pipeline::FrameStatus::reference)
        << name << " frame " << f.index << ": " << r.message;
    for (int id = 0; id < f.markers.size(); ++id) {
      ++e.expected;
      if (!r.markers.valid[static_cast<size_t>(id)]) continue;
      const double d = (r.markers.position[static_cast<size_t>(id)] - f.markers.position[static_cast<size_t>(id)]).norm();
      e.sum_sq += d * d;
      e.max = std::max(e.max, d);
      ++e.n;
    }
  }
  std::printf("[ measured ] %s: 3-D marker error rms %.4f mm, max %.4f mm, %ld of %ld markers\n", name.c_str(),
              e.rms(), e.max, e.n, e.expected);
  return e;
}
}  // namespace

TEST(VisionEndToEnd, MarkersMatchTheTruthWithTheTrueCalibration) {
  ONETIP_SWEEP_RUNS_IN_RELEASE_ONLY();
  sim::Simulator probe(sim::loadScenario((kSource / "samples" / "scenarios" / "press.yaml").string()));
  const StereoCalibration calib = probe.calibration();
  for (const auto& [name, frames] : std::vector<std::pair<std::string, int>>{
           {"press", 40}, {"slide_x", 60}, {"roll", 80}, {"two_finger", 40}, {"back_flat_back", 40}}) {
    const MarkerErrors e = playScenario(name, calib, frames);
    EXPECT_LE(e.rms(), 0.02) << name;
    EXPECT_LT(e.max, 0.1) << name << ": an id swap or a gross outlier";
    EXPECT_GE(double(e.n) / e.expected, 0.995) << name;
  }
}

TEST(VisionEndToEnd, MarkersMatchTheTruthWithTheCalibrationOnetipCalibrateMade) {
  ONETIP_SWEEP_RUNS_IN_RELEASE_ONLY();
  const test_support::ScratchDir scratch("onetip-e2e");
  const fs::path dir = scratch.path();
  const std::string cli = onetip::test::cliPath();
  ASSERT_EQ(run(cli + " sim --quiet --scenario " + (kSource / "samples/scenarios/calibration.yaml").string() +
                " --out " + (dir / "scene").string()),
            0);
  ASSERT_EQ(run(cli + " calibrate --flip-left --flip-right --pattern " + (dir / "scene/pattern.yaml").string() +
                " --input " + (dir / "scene/frames").string() + " --out " + (dir / "estimated.yaml").string()),
            0);
  const StereoCalibration estimated = loadCalibration((dir / "estimated.yaml").string());
  for (const auto& [name, frames] : std::vector<std::pair<std::string, int>>{{"press", 40}, {"slide_x", 60}}) {
    const MarkerErrors e = playScenario(name, estimated, frames);
    EXPECT_LE(e.rms(), 0.03) << name;
    EXPECT_GE(double(e.n) / e.expected, 0.995) << name;
  }
}

TEST(VisionEndToEnd, VisibleMarkersKeepTheirIdsWith20PercentOccluded) {
  sim::Simulator probe(sim::loadScenario((kSource / "samples" / "scenarios" / "press.yaml").string()));
  const MarkerErrors e = playScenario("press", probe.calibration(), 40, 5);
  EXPECT_LT(e.max, 0.1) << "a visible marker took another's id";
  EXPECT_LE(e.rms(), 0.02);
  EXPECT_GT(double(e.n) / e.expected, 0.7);  // the band hides about a fifth of the pad from frame 5 on
}

namespace {

// Each of OpenCV's stereo pairs 01-09 processed on its own (a one-frame
// folder: that frame is its own rest state) with a calibration: every one of
// the 54 inner corners is found and triangulated, neighbour spacing within
// 0.5% of a square, the board flat.
void expectWholeBoards(const std::string& calib, const std::string& label) {
  const std::string cli = onetip::test::cliPath();
  const std::string pattern = (kReal / "reference" / "pattern_9x6_nominal25mm.yaml").string();
  const double square = 25.0;
  for (int pair = 1; pair <= 9; ++pair) {
    char name[32];
    std::snprintf(name, sizeof name, "pair%02d.png", pair);
    const test_support::ScratchDir scratch("onetip-e2e");
    const fs::path dir = scratch.path();
    fs::create_directories(dir / "frames");
    fs::copy_file(kReal / "sbs" / name, dir / "frames" / name);
    ASSERT_EQ(run(cli + " process --quiet --calib " + calib + " --pattern " + pattern + " --input " +
                  (dir / "frames").string() + " --out " + (dir / "pose.csv").string() + " --markers " +
                  (dir / "markers.csv").string()),
              0)
        << label << " " << name;
    const CsvTable t = readCsv((dir / "markers.csv").string());
    ASSERT_EQ(t.rows.size(), 54u) << label << " " << name << ": all 54 corners, as frame 0";
    std::vector<Eigen::Vector3d> p(54);
    for (const auto& row : t.rows) {
      EXPECT_EQ(row[0], "0");
      p[static_cast<size_t>(std::stoi(row[1]))] = {std::stod(row[2]), std::stod(row[3]), std::stod(row[4])};
    }
    // neighbour spacing along rows and columns: one square
    double sum = 0;
    int links = 0;
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 9; ++c) {
        if (c + 1 < 9) sum += (p[r * 9 + c + 1] - p[r * 9 + c]).norm(), ++links;
        if (r + 1 < 6) sum += (p[(r + 1) * 9 + c] - p[r * 9 + c]).norm(), ++links;
      }
    const double spacing = sum / links;
    // planarity: in S the board is the z = 0 plane of its own rest frame
    double plane_sq = 0;
    for (const auto& q : p) plane_sq += q.z() * q.z();
    const double planarity = std::sqrt(plane_sq / 54) / square;
    std::printf("[ measured ] %s %s: 54/54 corners, mean spacing %.4f squares, planarity %.4f squares rms\n", label.c_str(),
                name, spacing / square, planarity);
    EXPECT_NEAR(spacing / square, 1.0, 0.005) << label << " " << name;
    EXPECT_LE(planarity, 0.025) << label << " " << name;
  }
}

}  // namespace

TEST(VisionEndToEnd, RealPhotosThroughOnetipProcessReproduceTheBoard) {
  expectWholeBoards((kReal / "reference" / "reference_calib_sbs_pairs01-09.yaml").string(), "reference calibration");
}

TEST(VisionEndToEnd, RealPhotosWithTheCalibrationOnetipCalibrateMadeFindEveryCorner) {
  const test_support::ScratchDir scratch("onetip-e2e-calib");
  const std::string calib = (scratch.path() / "calib.yaml").string();
  ASSERT_EQ(run(std::string(onetip::test::cliPath()) + " calibrate --pattern " +
                (kReal / "reference" / "pattern_9x6_nominal25mm.yaml").string() + " --input " + (kReal / "sbs").string() +
                " --out " + calib),
            0);
  expectWholeBoards(calib, "onetip calibrate");
}

TEST(VisionEndToEnd, BadFramesAreSkippedAndCountedAndTheStreamGoesOn) {
  const test_support::ScratchDir scratch("onetip-e2e");
  const fs::path dir = scratch.path();
  const std::string cli = onetip::test::cliPath();
  ASSERT_EQ(run(cli + " sim --quiet --frames 6 --scenario " + (kSource / "samples/scenarios/press.yaml").string() +
                " --out " + (dir / "sim").string()),
            0);
  const fs::path frames = dir / "sim" / "frames";
  // frame 2 truncated, frame 3 the wrong size, frame 4 blank
  fs::resize_file(frames / "000002.png", fs::file_size(frames / "000002.png") / 3);
  cv::imwrite((frames / "000003.png").string(), cv::Mat(100, 200, CV_8UC1, cv::Scalar(128)));
  cv::imwrite((frames / "000004.png").string(), cv::Mat(1080, 1920, CV_8UC1, cv::Scalar(0)));
  const std::string base = cli + " process --quiet --calib " + (dir / "sim/calib.yaml").string() + " --pattern " +
                           (dir / "sim/pattern.yaml").string() + " --input " + frames.string();
  ASSERT_EQ(run(base + " --out " + (dir / "pose.csv").string()), 0);
  const CsvTable pose = readCsv((dir / "pose.csv").string());
  std::vector<std::string> written;
  for (const auto& row : pose.rows) written.push_back(row[0]);
  EXPECT_EQ(written, (std::vector<std::string>{"0", "1", "5"}));

  // a calibration whose image size disagrees with every frame: one clear error, no output
  std::string text;
  {
    std::ifstream in(dir / "sim/calib.yaml");
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  text.replace(text.find("image_width: 1920"), 17, "image_width: 1280");
  text.replace(text.find("split_x: 960"), 12, "split_x: 640");
  std::ofstream(dir / "wrong_size.yaml") << text;
  const fs::path out = dir / "none.csv";
  EXPECT_NE(run(cli + " process --calib " + (dir / "wrong_size.yaml").string() + " --pattern " +
                (dir / "sim/pattern.yaml").string() + " --input " + frames.string() + " --out " + out.string()),
            0);
  EXPECT_FALSE(fs::exists(out));
}
