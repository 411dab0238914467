// Tiny inputs that asked for unbounded work, and values that were accepted
// without complaint (issue 17): each is refused with exit status 2, a message
// naming the option or the file, line and column, and no output file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "cli_runner.hpp"
#include "haptics/dataset_binary.hpp"
#include "scratch_dir.hpp"
#include "test_paths.hpp"

namespace {

using namespace onetip;
using namespace onetip::test_support;
namespace fs = std::filesystem;

const std::string kPress = shippedScenario("press");

TEST(HostileValues, CollectStepIsBoundedByItsCost) {
  const ScratchDir dir("onetip-hostile-values");
  for (const char* step : {"1e-9", "0.1", "1.6"})
    expectRefused(runCli("collect --quiet --step " + std::string(step) + " --out " + dir.file("d.csv"), dir.file("e")),
                  "configurations");
  EXPECT_FALSE(anyEntryContains(dir.path(), "d.csv"));
}

TEST(HostileValues, DatasetsWithTooManyChannelsOrNonFiniteValuesAreRefused) {
  const ScratchDir dir("onetip-hostile-values");
  std::ofstream(dir.file("q.csv")) << "s1\n1\n";
  const auto render = [&](const std::string& dataset) {
    return runCli("render --dataset " + dataset + " --queries " + dir.file("q.csv") + " --out " + dir.file("m.csv"),
                  dir.file("e"));
  };
  {  // 4,000 channels (53 s and 520 MB to build the search space): refused at the header
    std::ofstream wide(dir.file("wide.csv"));
    wide << "m1,m2,m3";
    for (int i = 1; i <= 4000; ++i) wide << ",s" << i;
    wide << "\n30,30,30";
    for (int i = 1; i <= 4000; ++i) wide << ",0";
    wide << "\n";
  }
  expectRefused(render(dir.file("wide.csv")), "line 1: 4000 sensed channels");
  std::ofstream(dir.file("big.csv")) << "m1,m2,m3,s1\n30,30,30,1\n60,60,60,1e39\n";
  expectRefused(render(dir.file("big.csv")), "line 3, column s1");
  std::ofstream(dir.file("nan.csv")) << "m1,m2,m3,s1\n30,30,30,nan\n";
  expectRefused(render(dir.file("nan.csv")), "line 2, column s1");

  // a NaN in a binary dataset whose checksum was recomputed over it
  haptics::TactileDataset d;
  d.channels = 2;
  d.append({30, 30, 30}, {1, 2});
  d.append({60, 60, 60}, {3, 4});
  const std::string bin = dir.file("nan.bin");
  haptics::writeDatasetBinary(d, bin);
  std::string bytes = readText(bin);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(bytes.data() + 24 + 4 * 5 + 4 * 4, &nan, 4);  // row 2, s2
  const std::uint64_t sum = haptics::fnv1a64(bytes.data(), bytes.size() - 8);
  std::memcpy(bytes.data() + bytes.size() - 8, &sum, 8);
  std::ofstream(bin, std::ios::binary | std::ios::trunc) << bytes;
  expectRefused(render(bin), "row 2, column s2");
  EXPECT_FALSE(fs::exists(dir.file("m.csv")));
}

TEST(HostileValues, CommandOptionsOutOfRangeAreRefused) {
  const ScratchDir dir("onetip-hostile-values");
  // refused before the port is opened: the port does not exist
  expectRefused(runCli("servo --port " + dir.file("tty") + " --angles 90,90,90,90", dir.file("e")), "exactly three");
  expectRefused(runCli("spnav --input sim:" + kPress + " --socket " + dir.file("s") + " --wait-client -5", dir.file("e")),
                "--wait-client");
  expectRefused(runCli("spnav --input sim:" + kPress + " --socket " + dir.file("s") + " --idle-timeout 0", dir.file("e")),
                "--idle-timeout");
  std::ofstream(dir.file("o.yaml")) << "%YAML:1.0\n---\nmin_markers: 2147483647\n";
  expectRefused(runCli("spnav --input sim:" + kPress + " --socket " + dir.file("s") + " --options " + dir.file("o.yaml"),
                       dir.file("e")),
                "min_markers");
  EXPECT_FALSE(fs::exists(dir.file("s")));
}

}  // namespace
