// Session folders (capture/session_source.hpp): decoded frames are kept as
// lossless PNG and replay bit-identical with their recorded indices and
// timestamps; a hostile session.csv is refused naming the line before any
// frame is read. (MJPEG kept as delivered: test_v4l2_source.cpp.)
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "capture/open_frame_source.hpp"
#include "capture/session_source.hpp"
#include "capture/session_writer.hpp"
#include "input_error_of.hpp"
#include "scratch_dir.hpp"

namespace {

using namespace onetip;
using namespace onetip::capture;
namespace fs = std::filesystem;

TEST(SessionSource, DecodedFramesReplayBitIdenticalWithTheirIndicesAndTimes) {
  const test_support::ScratchDir dir("onetip-session");
  std::vector<Frame> live;
  SessionWriter writer(dir.path().string());
  for (int i = 0; i < 3; ++i) {
    Frame f;
    f.status = FrameStatus::ok;
    f.index = 3 * i + 1;
    f.timestamp_s = i / 30.0 + 1e-9;  // needs all 17 digits to round-trip
    f.grey.create(90, 120, CV_8UC1);
    cv::randu(f.grey, 0, 256);
    writer.add(f);
    live.push_back(f);
  }
  writer.finish();
  EXPECT_TRUE(isSessionFolder(dir.path().string()));
  const auto source = openFrameSource(dir.path().string());  // a session wherever a source is taken
  for (const Frame& l : live) {
    const Frame r = source->next();
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_EQ(r.index, l.index);
    EXPECT_EQ(r.timestamp_s, l.timestamp_s);
    EXPECT_EQ(cv::norm(r.grey, l.grey, cv::NORM_INF), 0.0);
  }
  EXPECT_EQ(source->next().status, FrameStatus::end);
}

TEST(SessionSource, HostileSessionFilesAreRefusedNamingTheLine) {
  const test_support::ScratchDir dir("onetip-session");
  const auto refusal = [&](const std::string& csv) {
    std::ofstream(dir.path() / "session.csv", std::ios::trunc) << csv;
    return test_support::inputErrorOf([&] { SessionSource s(dir.path().string()); });
  };
  EXPECT_NE(refusal("frame,time,file\n0,0,frames/0.png\n").find("line 1"), std::string::npos);
  EXPECT_NE(refusal("frame,timestamp_s,file\n").find("no recorded frames"), std::string::npos);
  EXPECT_NE(refusal("frame,timestamp_s,file\n0,0,frames/a.png\n0,1,frames/b.png\n").find("line 3, column frame"),
            std::string::npos);
  EXPECT_NE(refusal("frame,timestamp_s,file\n0,1,frames/a.png\n1,0.5,frames/b.png\n").find("line 3, column timestamp_s"),
            std::string::npos);
  EXPECT_NE(refusal("frame,timestamp_s,file\n0,nan,frames/a.png\n").find("line 2"), std::string::npos);
  EXPECT_NE(refusal("frame,timestamp_s,file\n-1,0,frames/a.png\n").find("line 2, column frame"), std::string::npos);
  for (const char* escape : {"frames/../../etc/passwd", "/etc/passwd", "frames/", "frames/a/b.png", "a.png"})
    EXPECT_NE(refusal(std::string("frame,timestamp_s,file\n0,0,") + escape + "\n").find("line 2, column file"),
              std::string::npos)
        << escape;
  // a frame file that is missing or hostile is a counted skip, not an error
  fs::create_directory(dir.path() / "frames");
  std::ofstream(dir.path() / "frames/b.png") << "junk";
  std::ofstream(dir.path() / "session.csv", std::ios::trunc) << "frame,timestamp_s,file\n0,0,frames/a.png\n1,1,frames/b.png\n";
  SessionSource s(dir.path().string());
  EXPECT_EQ(s.next().status, FrameStatus::skipped);
  EXPECT_EQ(s.next().status, FrameStatus::skipped);
  EXPECT_EQ(s.next().status, FrameStatus::end);
  EXPECT_EQ(s.counters().skipped, 2);
}

}  // namespace
