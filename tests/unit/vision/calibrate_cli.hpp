// Running `onetip calibrate` from a test: exit status and everything printed.
#pragma once

#include <array>
#include <cstdio>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "test_paths.hpp"

namespace onetip::test {

struct CliRun {
  int status = -1;
  std::string out;  // stdout + stderr
};

inline CliRun runCalibrate(const std::string& args) {
  CliRun run;
  const std::string cmd = std::string(cliPath()) + " calibrate " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  if (pipe == nullptr) return run;
  std::array<char, 512> buf{};
  while (fgets(buf.data(), buf.size(), pipe) != nullptr) run.out += buf.data();
  run.status = pclose(pipe);
  return run;
}

inline std::string lastLine(const std::string& text) {
  std::string t = text;
  while (!t.empty() && t.back() == '\n') t.pop_back();
  return t.substr(t.rfind('\n') == std::string::npos ? 0 : t.rfind('\n') + 1);
}

// OpenCV's side-by-side pairs pair01..pair09 (640-pixel halves) from
// `sbs_dir` to `out_dir`, with the chosen halves mirrored as mirror optics
// would show them.
inline void writeMirroredPairs(const std::string& sbs_dir, const std::string& out_dir, bool left, bool right) {
  for (int i = 1; i <= 9; ++i) {
    const std::string name = "pair0" + std::to_string(i) + ".png";
    cv::Mat f = cv::imread(sbs_dir + "/" + name, cv::IMREAD_GRAYSCALE);
    for (const int x0 : {left ? 0 : -1, right ? 640 : -1})
      if (x0 >= 0) cv::flip(f(cv::Rect(x0, 0, 640, 480)).clone(), f(cv::Rect(x0, 0, 640, 480)), 1);
    cv::imwrite(out_dir + "/" + name, f);
  }
}

}  // namespace onetip::test
