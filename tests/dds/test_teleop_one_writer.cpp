// tests/dds/test_teleop_one_writer.cpp — without DDS Security, `onetip
// teleop` follows one writer of haptic/sensed (dds/writer_follower.hpp): a
// second writer, even one ten times faster or announcing the same sensor
// name, cannot take the platform over. The writers are forked publishers
// (publisher_process.hpp) of configuration A (the followed one) and B (the
// others, well beyond A on every servo). Checked on the emulated Maestro: the
// platform reached A's command and no target ever went beyond it towards B;
// teleop named the writer it followed and counted the others' samples; and
// a faster second writer did not push the followed one's samples out of the
// reader's one-sample history (the choice is a topic filter, ahead of it).
#include <algorithm>
#include <memory>

#include "publisher_process.hpp"
#include "teleop_fixture.hpp"

namespace {

using namespace onetip;
using namespace onetip::teleop_test;
using test_support::PublisherPlan;

class OneWriter : public TeleopOverDds {
 protected:
  void SetUp() override {
    TeleopOverDds::SetUp();
    a_ = rowOf(dataset_, rowWithAngles(dataset_, 60, 100));
    b_ = rowOf(dataset_, rowWithAngles(dataset_, 150, 195));
    want_a_ = renderer_.render(a_.data(), 4).command;
    want_b_ = renderer_.render(b_.data(), 4).command;
  }
  PublisherPlan plan(const std::string& sensor, const std::vector<double>& v, double rate_hz, double seconds,
                     double start_after_s) const {
    PublisherPlan p{net_, "", std::nullopt, sensor, v, rate_hz, seconds, true, start_after_s};
    return p;
  }
  // Runs teleop with the given extra options until the publishers are done; returns its log.
  std::string runTeleop(const std::string& extra, std::vector<PublisherPlan> plans) {
    std::vector<std::unique_ptr<test_support::ChildProcess>> publishers;
    for (const auto& p : plans)
      publishers.push_back(std::make_unique<test_support::ChildProcess>(test_support::publisherBody(p)));
    devices::testing::MaestroEmulator maestro;
    Launch how;
    how.extra = extra;
    test_support::ChildProcess teleop(teleopCommand(maestro.path(), 100, 0, how), dir_.file("teleop.log"));
    for (auto& p : publishers) EXPECT_EQ(p->wait(20), 1) << "a publisher never matched teleop";
    teleop.signal(SIGINT);
    EXPECT_EQ(teleop.wait(30), 0) << teleop.log();
    std::printf("%s", teleop.log().c_str());
    const std::vector<Period> periods = periodsOf(maestro);
    EXPECT_TRUE(std::any_of(periods.begin(), periods.end(), [&](const Period& p) { return near(p, want_a_); }))
        << "the followed writer did not drive the platform to A's command";
    for (size_t c = 0; c < 3; ++c) {
      double seen = kRest;
      for (const auto& p : periods) seen = std::max(seen, p.deg[c]);
      EXPECT_LE(seen, std::max(want_a_[c], kRest) + kTol) << "servo " << c << " moved towards B (" << want_b_[c]
                                                           << " deg), another writer's command";
    }
    return teleop.log();
  }
  static long ignoredOf(const std::string& log) { return countIn(log, R"(ignored (\d+) samples of other writers)"); }

  std::vector<double> a_, b_;
  std::array<double, 3> want_a_{}, want_b_{};
};

TEST_F(OneWriter, FollowsTheFirstWriterAndIgnoresAFasterSecondOne) {
  const std::string log = runTeleop("", {plan("biotac_like", a_, 100, 2.0, 0), plan("intruder", b_, 1000, 1.0, 0.5)});
  EXPECT_NE(log.find("teleop: following writer "), std::string::npos) << "teleop did not name the writer it follows";
  EXPECT_NE(log.find("(sensor 'biotac_like'); samples of any other writer are ignored"), std::string::npos);
  EXPECT_GT(ignoredOf(log), 500) << "about 1,000 samples of the second writer came";
  // Refused before the reader's one-slot history, the faster writer's samples push none of the followed one's out.
  const long received = countIn(log, R"(received (\d+) sensed vectors)");
  EXPECT_LE(received, 2.0 * 100 + 2) << "more than the followed writer sent";
  EXPECT_GE(received, 0.9 * 2.0 * 100) << "the second writer pushed the followed writer's samples out";
}

TEST_F(OneWriter, SensorOptionFollowsTheNamedWriterEvenWhenAnotherCameFirstOrCopiesTheName) {
  const std::string log = runTeleop("--sensor tip_left", {plan("other", b_, 100, 2.5, 0),
                                                          plan("tip_left", a_, 100, 1.5, 0.5),
                                                          plan("tip_left", b_, 1000, 1.0, 1.0)});
  EXPECT_NE(log.find("(sensor 'tip_left'); samples of any other writer are ignored"), std::string::npos) << log;
  EXPECT_GT(ignoredOf(log), 50 + 500) << "the first writer's ~50 samples before and the copy's ~1,000";
}

}  // namespace
