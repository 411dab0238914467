// `onetip render` as docs/reference.md states it: output and timing files, and
// one-line errors with no output file on bad input.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/csv_table.hpp"
#include "haptics/knn_renderer.hpp"
#include "haptics/tactile_dataset.hpp"
#include "scratch_dir.hpp"
#include "test_paths.hpp"

using namespace onetip;
using namespace onetip::haptics;
namespace fs = std::filesystem;

namespace {
struct Run {
  int status;
  std::string output;
};
Run run(const std::string& args) {
  const std::string cmd = std::string(onetip::test::cliPath()) + " render " + args + " 2>&1";
  FILE* p = ::popen(cmd.c_str(), "r");
  std::string out;
  char buf[512];
  while (std::fgets(buf, sizeof buf, p)) out += buf;
  return {::pclose(p), out};
}
void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }
}  // namespace

TEST(RenderCli, WritesCommandsAndTimingPerConventions) {
  const test_support::ScratchDir scratch("onetip-render-cli");
  const auto dir = scratch.path();
  write(dir / "d.csv", "m1,m2,m3,s1,s2\n30,30,30,0,0\n60,90,120,10,1\n195,195,195,20,4\n90,60,30,5,3\n");
  write(dir / "q.csv", "s1,s2\n0,0\n9,1.5\n30,-2\n");
  const auto r = run("--dataset " + (dir / "d.csv").string() + " --queries " + (dir / "q.csv").string() +
                     " --neighbors 2 --out " + (dir / "m.csv").string() + " --timing " + (dir / "t.csv").string());
  ASSERT_EQ(r.status, 0) << r.output;
  const CsvTable m = readCsv((dir / "m.csv").string());
  ASSERT_EQ(m.header, (std::vector<std::string>{"m1", "m2", "m3"}));
  ASSERT_EQ(m.rows.size(), 3u);
  const KnnRenderer reference(readDatasetCsv((dir / "d.csv").string()));
  const QuerySet q = readQueriesCsv((dir / "q.csv").string());
  for (size_t i = 0; i < 3; ++i) {
    const auto expected = reference.render(q.row(i), 2);
    for (size_t j = 0; j < 3; ++j) EXPECT_NEAR(std::stod(m.rows[i][j]), expected.command[j], 1e-5);
  }
  EXPECT_EQ(m.rows[0][0], "30");  // exact match of row 1
  const CsvTable t = readCsv((dir / "t.csv").string());
  ASSERT_EQ(t.header, (std::vector<std::string>{"what", "ms"}));
  ASSERT_EQ(t.rows.size(), 3u);
  EXPECT_EQ(t.rows[0][0], "load");
  EXPECT_EQ(t.rows[1][0], "build");
  EXPECT_EQ(t.rows[2][0], "query");
  for (const auto& row : t.rows) EXPECT_GE(std::stod(row[1]), 0.0);
}

TEST(RenderCli, BadInputGivesOneLineErrorAndNoOutput) {
  const test_support::ScratchDir scratch("onetip-render-cli");
  const auto dir = scratch.path();
  write(dir / "d.csv", "m1,m2,m3,s1,s2\n30,30,30,0,0\n");
  write(dir / "q3.csv", "s1,s2,s3\n1,2,3\n");
  write(dir / "bad.csv", "s1,s2\n1,x\n");
  const std::string out = (dir / "never.csv").string();
  const std::string d = " --dataset " + (dir / "d.csv").string();
  for (const std::string& args :
       {d + " --queries " + (dir / "q3.csv").string() + " --out " + out,
        d + " --queries " + (dir / "bad.csv").string() + " --out " + out,
        d + " --queries " + (dir / "missing.csv").string() + " --out " + out,
        d + " --queries " + (dir / "q3.csv").string() + " --neighbors 0 --out " + out,
        std::string(" --queries ") + (dir / "q3.csv").string() + " --out " + out}) {
    const auto r = run(args);
    EXPECT_NE(r.status, 0) << args;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(fs::exists(out)) << args;
  }
}

// A finite float32 query can still overflow the standardised float search
// space (3e38 over a channel with sd 0.0005): no row is a finite distance from
// it, and the command says so instead of writing a NaN (or a stale) command.
TEST(RenderCli, QueryThatOverflowsTheSearchSpaceIsRefused) {
  const test_support::ScratchDir scratch("onetip-render-cli");
  const auto dir = scratch.path();
  write(dir / "d.csv", "m1,m2,m3,s1\n30,30,30,0\n60,60,60,0.001\n");
  write(dir / "q.csv", "s1\n0.0005\n3e38\n");
  const std::string out = (dir / "m.csv").string();
  const auto r = run("--dataset " + (dir / "d.csv").string() + " --queries " + (dir / "q.csv").string() + " --out " + out);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("query 2: no dataset row is a finite distance"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_FALSE(fs::exists(out));
}
