// tests/dds/test_writer_follower.cpp — the choice of the one writer teleop
// follows (dds/writer_follower.hpp), without DDS: writer handles and sensor
// names as the topic filter sees them, then the name the reading side gives it.
#include <gtest/gtest.h>

#include "dds/writer_follower.hpp"
#include "input_error_of.hpp"

namespace {

using namespace onetip;
using onetip::test_support::inputErrorOf;

std::string noGuid() { return "unknown"; }

TEST(WriterFollower, FollowsTheFirstWriterAndCountsTheOthers) {
  dds::WriterFollower f;
  EXPECT_FALSE(f.following());
  EXPECT_TRUE(f.admit(11));
  EXPECT_TRUE(f.admit(22)) << "every writer is let in until one is followed";
  EXPECT_TRUE(f.taken(11, "biotac_like", noGuid));
  EXPECT_TRUE(f.following());
  EXPECT_FALSE(f.taken(22, "biotac_like", noGuid)) << "a second writer copying the name, let in before the choice";
  EXPECT_FALSE(f.admit(22));
  EXPECT_TRUE(f.admit(11));
  EXPECT_TRUE(f.taken(11, "renamed", noGuid)) << "the followed writer is followed whatever it announces";
  EXPECT_EQ(f.ignored(), 2u);
}

TEST(WriterFollower, NamedSensorIsWaitedForAndOthersBeforeItAreIgnored) {
  dds::WriterFollower f("tip_left");
  EXPECT_TRUE(f.admit(11));
  EXPECT_FALSE(f.taken(11, "other", noGuid));
  EXPECT_FALSE(f.taken(12, nullptr, noGuid)) << "a sample that could not be decoded names no sensor";
  EXPECT_FALSE(f.following());
  EXPECT_TRUE(f.taken(13, "tip_left", noGuid));
  EXPECT_FALSE(f.admit(14)) << "a later writer (announcing the same name or not)";
  EXPECT_FALSE(f.admit(11));
  EXPECT_FALSE(f.taken(11, "other", noGuid));
  EXPECT_EQ(f.ignored(), 5u);
}

TEST(WriterFollower, TheFollowedWriterIsAnnouncedOnce) {
  dds::WriterFollower f;
  int told = 0;
  f.locked = [&](const dds::FollowedWriter& w) {
    ++told;
    EXPECT_EQ(w.guid, "110d7d6:589020a3:b7da8088:203");
    EXPECT_EQ(w.sensor, "biotac_like");
  };
  int asked = 0;
  for (int i = 0; i < 3; ++i)
    EXPECT_TRUE(f.taken(11, "biotac_like", [&] {
      ++asked;
      return std::string("110d7d6:589020a3:b7da8088:203");
    }));
  EXPECT_EQ(told, 1);
  EXPECT_EQ(asked, 1) << "the GUID is looked up once";
  EXPECT_EQ(f.followed().sensor, "biotac_like");
}

TEST(WriterFollower, SensorNamesAreCheckedWithTheOptionNamed) {
  EXPECT_NE(inputErrorOf([] { dds::validateSensorName("", "--sensor"); }).find("--sensor ''"), std::string::npos);
  EXPECT_NE(inputErrorOf([] { dds::validateSensorName("a b", "--sensor"); }).find("[A-Za-z0-9_.-]"), std::string::npos);
  EXPECT_FALSE(inputErrorOf([] { dds::validateSensorName(std::string(65, 'a'), "--sensor"); }).empty());
  EXPECT_TRUE(inputErrorOf([] { dds::validateSensorName("tip_left-2.0", "--sensor"); }).empty());
  EXPECT_FALSE(inputErrorOf([] { dds::WriterFollower f("bad name"); }).empty());
}

}  // namespace
