// Configuration files as people write them (core/config_file.hpp): plain YAML
// without OpenCV's "%YAML:1.0" line and JSON are read; malformed files are
// refused with "<file>:<line>: key '<key>': ..." naming the file, the line the
// key is on and the key; hostile input (deep nesting, huge files, duplicate
// keys, integers that would wrap, absurd numbers) is an InputError, not a crash.
#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/core.hpp>
#include <string>

#include "core/calibration.hpp"
#include "core/config_file.hpp"
#include "core/pattern.hpp"
#include "input_error_of.hpp"
#include "pipeline/options_io.hpp"
#include "scratch_dir.hpp"
#include "sim/scenario.hpp"

using namespace onetip;
using onetip::test_support::inputErrorOf;

namespace {

class ConfigFiles : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) {
    const std::string path = scratch_.file(name);
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  test_support::ScratchDir scratch_{"onetip-config"};
};

const std::string kTouch = "name: t\nindenters:\n  - shape: sphere\n    radius: 5\n    keyframes:\n";

}  // namespace

TEST_F(ConfigFiles, PlainYamlWithoutAHeaderLineIsAccepted) {
  const MarkerPattern p = loadPattern(write("pattern.yaml", "rows: 6\ncols: 9\nsquare_mm: 25\n"));
  EXPECT_EQ(p.rows, 6);
  EXPECT_EQ(p.cols, 9);
  EXPECT_EQ(p.square_mm, 25.0);

  const pipeline::PipelineOptions o = pipeline::loadPipelineOptions(
      write("options.yaml", "# my options\nqueue_capacity: 8\nlossless: true\nfilter: one_euro\nfilter_beta: 0.25\n"
                            "gain: [1, 1, 2, 1, 1, 1]\n"));
  EXPECT_EQ(o.queue_capacity, 8);
  EXPECT_TRUE(o.lossless);
  EXPECT_EQ(o.processor.pose.filter.kind, input::FilterKind::one_euro);
  EXPECT_EQ(o.processor.pose.filter.beta, 0.25);
  EXPECT_EQ(o.processor.pose.shaping.gain[2], 2.0);

  const sim::Scenario sc = sim::loadScenario(
      write("scenario.yaml", kTouch + "      - {t: 0, depth: -0.5}\n      - t: 1\n        depth: 1.5\n"));
  ASSERT_EQ(sc.indenters.size(), 1u);
  ASSERT_EQ(sc.indenters[0].keyframes.size(), 2u);
  EXPECT_EQ(sc.indenters[0].keyframes[1].depth, 1.5);
}

TEST_F(ConfigFiles, JsonAndOpenCvFilesStillRead) {
  const MarkerPattern p = loadPattern(write("pattern.json", "{\n\t\"rows\": 7,\n\t\"cols\": 5,\n\t\"square_mm\": 1.5\n}\n"));
  EXPECT_EQ(p.rows, 7);
  EXPECT_EQ(p.square_mm, 1.5);

  // A calibration onetip writes is read back by onetip and by OpenCV alike.
  StereoCalibration c;
  c.image_width = 1280;
  c.image_height = 480;
  c.split_x = 640;
  c.K_left = c.K_right = cv::Matx33d(500, 0, 320, 0, 501, 240, 0, 0, 1);
  c.D_left = {-0.25, 0.1, 0.001, -0.002, 0.01};
  c.T = {-80, 0.5, 0.25};
  const std::string path = scratch_.file("calib.yaml");
  saveCalibration(c, path, 0.2);
  const StereoCalibration back = loadCalibration(path);
  EXPECT_EQ(back.K_left(1, 1), 501.0);
  EXPECT_EQ(back.D_left[4], 0.01);
  EXPECT_EQ(back.T[2], 0.25);
  cv::FileStorage opencv(path, cv::FileStorage::READ);
  ASSERT_TRUE(opencv.isOpened());
  cv::Mat K;
  opencv["K_left"] >> K;
  EXPECT_EQ(K.at<double>(0, 2), 320.0);
  EXPECT_EQ(static_cast<double>(opencv["rms_px"]), 0.2);
}

// Ten malformed files; each message names the file, the line and the key.
TEST_F(ConfigFiles, MalformedFilesNameFileLineAndKey) {
  struct Case {
    std::string name, text;
    std::function<void(const std::string&)> load;
    std::string line_key;  // ":<line>: key '<key>'"
    std::string why;
  };
  const auto pattern = [](const std::string& p) { loadPattern(p); };
  const auto options = [](const std::string& p) { pipeline::loadPipelineOptions(p); };
  const auto scenario = [](const std::string& p) { sim::loadScenario(p); };
  const auto calibration = [](const std::string& p) { loadCalibration(p); };
  const std::vector<Case> cases{
      {"p1.yaml", "cols: 9\nsquare_mm: 2\nrows: abc\n", pattern, ":3: key 'rows'",
       "expected an integer in [2, 1000], got \"abc\""},
      {"p2.yaml", "rows: 4294967313\ncols: 9\nsquare_mm: 2\n", pattern, ":1: key 'rows'", "got \"4294967313\""},
      {"p3.yaml", "rows: 6\ncols: 9\nrows: 7\nsquare_mm: 2\n", pattern, ":3: key 'rows'", "given twice"},
      {"p4.json", "{\"rows\": 6,\n \"cols\": 9,\n \"square_mm\": -1}\n", pattern, ":3: key 'square_mm'",
       "expected a number in"},
      {"o1.yaml", "lossless: 1\nqueue_capacty: 3\n", options, ":2: key 'queue_capacty'", "unknown key"},
      {"o2.yaml", "\n\nfilter_beta: .inf\n", options, ":3: key 'filter_beta'", "got \".inf\""},
      {"o3.yaml", "gain: [1, 2, 3]\n", options, ":1: key 'gain'", "a list of 6 numbers"},
      {"o4.yaml", "queue_capacity: 4\nqueue_capacity_x: 1\nrelease_mm: 2\n", options, ":2: key 'queue_capacity_x'",
       "unknown key"},
      {"s1.yaml", kTouch + "      - {t: 0}\ncamera:\n  k1: 1e200\n", scenario, ":8: key 'camera.k1'", "got \"1e200\""},
      {"s2.yaml", kTouch + "      - {t: 0, depth: 1}\n      - {t: 0, depth: 2}\n", scenario,
       ":7: key 'indenters[0].keyframes[1].t'", "greater than the previous"},
      {"c1.yaml", "image_width: 1280\nimage_height: 480\nsplit_x: 5000\n", calibration, ":3: key 'split_x'",
       "expected an integer in [1, 1279]"},
  };
  for (const Case& c : cases) {
    const std::string path = write(c.name, c.text);
    const std::string message = inputErrorOf([&] { c.load(path); });
    EXPECT_EQ(message.rfind(path + c.line_key + ": ", 0), 0u) << c.name << ": " << message;
    EXPECT_NE(message.find(c.why), std::string::npos) << c.name << ": " << message;
  }
}

TEST_F(ConfigFiles, HostileInputIsAnInputErrorNotACrash) {
  const std::string deep = write("deep.yaml", "a: " + std::string(50000, '['));
  EXPECT_NE(inputErrorOf([&] { loadPattern(deep); }).find(deep + ":1: "), std::string::npos);
  const std::string nested = write("nested.yaml", "rows: " + std::string(40, '[') + std::string(40, ']') + "\n");
  EXPECT_NE(inputErrorOf([&] { loadPattern(nested); }).find("nested deeper than"), std::string::npos);
  const std::string null_key = write("nullkey.yaml", "a: { : 1}\n");
  EXPECT_NE(inputErrorOf([&] { ConfigNode::load(null_key); }).find(null_key + ":1: a key must be a plain name"),
            std::string::npos);
  const std::string dash = write("dash.yaml", "-\n");
  EXPECT_NE(inputErrorOf([&] { loadPattern(dash); }).find(dash + ":1: expected a map of keys, got a list"),
            std::string::npos);
  const std::string empty = write("empty.yaml", "");
  EXPECT_NE(inputErrorOf([&] { loadPattern(empty); }).find(empty + ":1: the file is empty"), std::string::npos);
  const std::string big = write("big.yaml", "rows: 6\n#" + std::string(kMaxConfigBytes, 'x') + "\n");
  EXPECT_NE(inputErrorOf([&] { loadPattern(big); }).find("at most"), std::string::npos);
  // Aliases repeating a subtree: nine times per level, 9^8 values when walked.
  std::string laughs = "a0: &a0 [1, 1, 1, 1, 1, 1, 1, 1, 1]\n";
  for (int i = 1; i <= 8; ++i) {
    const std::string prev = "*a" + std::to_string(i - 1);
    laughs += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [" + prev;
    for (int k = 0; k < 8; ++k) laughs += ", " + prev;
    laughs += "]\n";
  }
  const std::string bomb = write("laughs.yaml", laughs);
  EXPECT_NE(inputErrorOf([&] { ConfigNode::load(bomb); }).find("aliases"), std::string::npos);
  const std::string two_docs = write("two.yaml", "rows: 6\n---\nrows: 7\n");
  EXPECT_NE(inputErrorOf([&] { loadPattern(two_docs); }).find("more than one YAML document"), std::string::npos);
  // Found by fuzzing: yaml-cpp 0.7's LoadAll never returns on these two bytes.
  const std::string comma = write("comma.yaml", ",\n");
  EXPECT_FALSE(inputErrorOf([&] { loadPattern(comma); }).empty());
  const std::string header = write("header.yaml", "%YAML:1.0\n---\nrows: 6\ncols: 9\nsquare_mm: 25\n");
  EXPECT_NO_THROW(loadPattern(header));
}
