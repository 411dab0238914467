// Tactile dataset files: CSV and binary round trips, and the refusals of bad,
// corrupt, truncated or wrong-version files (one message, no partial output).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <random>

#include "core/error.hpp"
#include "haptics/dataset_binary.hpp"
#include "haptics/tactile_dataset.hpp"
#include "scratch_dir.hpp"
#include "input_error_of.hpp"

using namespace onetip;
using namespace onetip::haptics;
namespace fs = std::filesystem;
using onetip::test_support::inputErrorOf;

namespace {
TactileDataset randomDataset(int channels, int rows, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> angle(30, 195), value(-1e3, 1e4);
  TactileDataset d;
  d.channels = channels;
  for (int r = 0; r < rows; ++r) {
    std::vector<double> s(static_cast<size_t>(channels));
    for (double& v : s) v = value(rng) / 7.0;  // not exactly representable in decimal
    d.append({angle(rng), angle(rng), angle(rng)}, s);
  }
  return d;
}
std::vector<char> bytesOf(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}
void writeBytes(const fs::path& p, const std::vector<char>& b) {
  std::ofstream(p, std::ios::binary).write(b.data(), static_cast<std::streamsize>(b.size()));
}
}  // namespace

TEST(DatasetFiles, CsvRoundTripIsExact) {
  const test_support::ScratchDir scratch("onetip-dataset-files");
  const auto d = randomDataset(7, 50, 1);
  const auto path = (scratch.path() / "d.csv").string();
  writeDatasetCsv(d, path);
  std::ifstream in(path);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "m1,m2,m3,s1,s2,s3,s4,s5,s6,s7");
  const auto back = readDatasetCsv(path);
  EXPECT_EQ(back.channels, 7);
  EXPECT_EQ(back.commands, d.commands);
  EXPECT_EQ(back.sensed, d.sensed);
  EXPECT_EQ(loadDataset(path).sensed, d.sensed);
}

TEST(DatasetFiles, BinaryRoundTripIsExactAndSmallerThanCsv) {
  const test_support::ScratchDir scratch("onetip-dataset-files");
  const auto d = randomDataset(20, 300, 2);
  const auto dir = scratch.path();
  writeDatasetBinary(d, (dir / "d.bin").string());
  writeDatasetCsv(d, (dir / "d.csv").string());
  EXPECT_EQ(fs::file_size(dir / "d.bin"), 24u + 300u * 23u * 4u + 8u);
  EXPECT_LT(fs::file_size(dir / "d.bin"), fs::file_size(dir / "d.csv"));
  EXPECT_TRUE(isBinaryDataset((dir / "d.bin").string()));
  EXPECT_FALSE(isBinaryDataset((dir / "d.csv").string()));
  const auto back = loadDataset((dir / "d.bin").string());
  EXPECT_EQ(back.channels, 20);
  EXPECT_EQ(back.commands, d.commands);
  EXPECT_EQ(back.sensed, d.sensed);
}

TEST(DatasetFiles, Fnv1a64MatchesPublishedVectors) {
  EXPECT_EQ(fnv1a64("", 0), 0xcbf29ce484222325ULL);
  EXPECT_EQ(fnv1a64("a", 1), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(fnv1a64("foobar", 6), 0x85944171f73967e8ULL);
}

TEST(DatasetFiles, CorruptTruncatedAndWrongVersionBinariesAreRefused) {
  const test_support::ScratchDir scratch("onetip-dataset-files");
  const auto dir = scratch.path();
  const auto good = dir / "good.bin";
  writeDatasetBinary(randomDataset(5, 40, 3), good.string());
  const auto bytes = bytesOf(good);

  auto flipped = bytes;
  flipped[100] = static_cast<char>(flipped[100] ^ 0x10);
  writeBytes(dir / "flip.bin", flipped);
  EXPECT_NE(inputErrorOf([&] { readDatasetBinary((dir / "flip.bin").string()); }).find("corrupt"), std::string::npos);

  for (size_t keep : {size_t{10}, size_t{30}, bytes.size() - 1}) {
    writeBytes(dir / "cut.bin", std::vector<char>(bytes.begin(), bytes.begin() + static_cast<long>(keep)));
    EXPECT_NE(inputErrorOf([&] { loadDataset((dir / "cut.bin").string()); }).find("truncated"), std::string::npos)
        << keep;
  }

  auto version = bytes;
  version[8] = 9;
  writeBytes(dir / "v9.bin", version);
  EXPECT_NE(inputErrorOf([&] { readDatasetBinary((dir / "v9.bin").string()); }).find("version 9"), std::string::npos);

  auto magic = bytes;
  magic[0] = 'X';
  writeBytes(dir / "magic.bin", magic);
  EXPECT_NE(inputErrorOf([&] { readDatasetBinary((dir / "magic.bin").string()); }).find("bad magic"),
            std::string::npos);
}

TEST(DatasetFiles, BadCsvFilesNameTheProblem) {
  const test_support::ScratchDir scratch("onetip-dataset-files");
  const auto dir = scratch.path();
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  };
  EXPECT_NE(inputErrorOf([&] { readDatasetCsv(write("h.csv", "m1,m2,m4,s1\n1,2,3,4\n")); }).find("'m4', expected 'm3'"),
            std::string::npos);
  EXPECT_NE(inputErrorOf([&] { readDatasetCsv(write("n.csv", "m1,m2,m3\n1,2,3\n")); }).find("no sensed channels"),
            std::string::npos);
  EXPECT_NE(inputErrorOf([&] { readDatasetCsv(write("x.csv", "m1,m2,m3,s1\n1,2,3,abc\n")); }).find("column s1"),
            std::string::npos);
  EXPECT_NE(inputErrorOf([&] { readDatasetCsv(write("e.csv", "m1,m2,m3,s1\n")); }).find("no data rows"),
            std::string::npos);
  EXPECT_NE(inputErrorOf([&] { readQueriesCsv(write("q.csv", "s1,s3\n1,2\n")); }).find("'s3', expected 's2'"),
            std::string::npos);
  const auto q = readQueriesCsv(write("ok.csv", "s1,s2\n1,2\n3.5,-4\n"));
  EXPECT_EQ(q.size(), 2u);
  EXPECT_DOUBLE_EQ(q.row(1)[1], -4.0);
}

TEST(DatasetFiles, AFailedWriteLeavesNoFile) {
  const test_support::ScratchDir scratch("onetip-dataset-files");
  const auto dir = scratch.path();
  TactileDataset empty;
  empty.channels = 3;
  EXPECT_FALSE(inputErrorOf([&] { writeDatasetBinary(empty, (dir / "empty.bin").string()); }).empty());
  EXPECT_FALSE(fs::exists(dir / "empty.bin"));
  EXPECT_FALSE(inputErrorOf([&] { writeDatasetCsv(empty, (dir / "no_dir" / "d.csv").string()); }).empty());
}
