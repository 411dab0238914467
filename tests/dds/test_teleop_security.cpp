// tests/dds/test_teleop_security.cpp — with DDS Security (docs/dds/README.md,
// "Security"), only an authenticated sensor drives the platform. The test PKI
// comes from docs/dds/security/make-test-pki.sh, as a user makes it; `onetip
// teleop` runs as the identity `operator`, given through CYCLONEDDS_URI
// together with --interface and --peer (merged, dds/participant.hpp), and the
// sensor publishes configuration A at 100 Hz as `sensor`. Two rogues publish
// configuration B at 1 kHz for the whole run: one without DDS Security, one
// with an identity of the same name certified by a CA of its own. Checked:
// the platform reached A's command; no target ever went beyond A's towards
// B's; teleop received no more samples than the sensor sent (the rogues' ~6,000
// would show); neither rogue's writer ever matched a reader. On the loopback,
// and across two network namespaces (teleop in A, the publishers in B), which
// is skipped with the reason where namespaces cannot be made; there also
// without --interface and --peer (multicast discovery on the veth pair).
#include <algorithm>
#include <cstdlib>

#include "publisher_process.hpp"
#include "teleop_fixture.hpp"
#include "veth_namespaces.hpp"

namespace {

using namespace onetip;
using namespace onetip::teleop_test;
using test_support::PublisherPlan;

class SecureTeleop : public TeleopOverDds {
 protected:
  // Makes a PKI with identities `sensor` and `operator` in dir; empty on success, else why not.
  static std::string makePki(const std::string& dir) {
    const std::string log = dir + ".log";
    const std::string cmd = "bash " + std::string(test::sourceDir()) + "/docs/dds/security/make-test-pki.sh " + dir +
                            " sensor operator >" + log + " 2>&1";
    if (std::system(cmd.c_str()) == 0) return {};
    std::ifstream in(log);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::string uriOf(const std::string& pki, const std::string& name) const {
    return "file://" + dir_.file(pki) + "/" + name + ".xml";
  }

  // Where the publishers run (their namespace and network options) and how teleop is started.
  struct Sides {
    std::string publisher_netns;
    dds::DdsOptions publisher_net;
    std::string teleop_prefix;
    std::string teleop_network;
  };

  void runWithRogues(const Sides& sides) {
    const std::vector<double> a = rowOf(dataset_, rowWithAngles(dataset_, 60, 100));
    const std::vector<double> b = rowOf(dataset_, rowWithAngles(dataset_, 150, 195));
    const auto want_a = renderer_.render(a.data(), 4).command, want_b = renderer_.render(b.data(), 4).command;
    std::array<double, 3> highest{};  // the most each servo may show: A's command (or rest)
    for (size_t c = 0; c < 3; ++c) {
      highest[c] = std::max(want_a[c], kRest) + kTol;
      ASSERT_GT(want_b[c], highest[c] + 20) << "B must be well beyond A for the check to mean anything";
    }
    constexpr double kSensorSeconds = 1.0, kSensorHz = 100;
    const PublisherPlan sensor{sides.publisher_net, sides.publisher_netns, uriOf("pki", "sensor"), "biotac_like", a,
                               kSensorHz, kSensorSeconds, true};
    PublisherPlan rogue{sides.publisher_net, sides.publisher_netns, std::nullopt, "biotac_like", b, 1000, 0, false};
    test_support::ChildProcess plain_rogue(test_support::publisherBody(rogue));
    rogue.uri = uriOf("rogue_pki", "sensor");
    test_support::ChildProcess foreign_ca_rogue(test_support::publisherBody(rogue));
    test_support::ChildProcess publisher(test_support::publisherBody(sensor));

    // teleop runs until the sensor is done (its handshake takes longer under the sanitizers), the rogues throughout.
    devices::testing::MaestroEmulator maestro;
    Launch how;
    how.prefix = sides.teleop_prefix + " env CYCLONEDDS_URI=" + uriOf("pki", "operator");
    how.network = sides.teleop_network;
    test_support::ChildProcess teleop(teleopCommand(maestro.path(), 100, 0, how), dir_.file("teleop.log"));
    EXPECT_EQ(publisher.wait(20), 1) << "the authenticated sensor's writer never matched teleop";
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    teleop.signal(SIGINT);
    ASSERT_EQ(teleop.wait(30), 0) << teleop.log();
    std::printf("%s", teleop.log().c_str());
    plain_rogue.signal(SIGTERM);
    foreign_ca_rogue.signal(SIGTERM);
    EXPECT_EQ(plain_rogue.wait(20), 0) << "a reader matched the rogue without DDS Security";
    EXPECT_EQ(foreign_ca_rogue.wait(20), 0) << "a reader matched the rogue certified by another CA";

    const std::vector<Period> periods = periodsOf(maestro);
    EXPECT_TRUE(std::any_of(periods.begin(), periods.end(), [&](const Period& p) { return near(p, want_a); }))
        << "the authenticated sensor did not drive the platform to A's command\n" << teleop.log();
    for (size_t c = 0; c < 3; ++c) {
      double seen = kRest;
      for (const auto& p : periods) seen = std::max(seen, p.deg[c]);
      EXPECT_LE(seen, highest[c]) << "servo " << c << " moved towards a rogue's B (" << want_b[c] << " deg)";
    }
    const long received = countIn(teleop.log(), R"(received (\d+) sensed vectors)");
    EXPECT_GT(received, kSensorSeconds * kSensorHz / 2) << "the sensor's samples did not arrive";
    EXPECT_LE(received, kSensorSeconds * kSensorHz + 2) << "teleop received more than the sensor sent";
  }

  void SetUp() override {
    TeleopOverDds::SetUp();
    for (const char* pki : {"pki", "rogue_pki"})
      if (const std::string why = makePki(dir_.file(pki)); !why.empty())
        GTEST_SKIP() << "cannot make the test PKI (docs/dds/security/make-test-pki.sh): " << why;
  }
};

TEST_F(SecureTeleop, OnTheLoopbackOnlyTheAuthenticatedSensorGetsThrough) {
  runWithRogues({"", net_, "", "--interface lo --peer 127.0.0.1"});
}

TEST_F(SecureTeleop, AcrossTwoNetworkNamespacesOnlyTheAuthenticatedSensorGetsThrough) {
  test_support::VethNamespaces ns;
  if (const std::string why = ns.create(); !why.empty()) GTEST_SKIP() << "network namespaces unavailable here: " << why;
  dds::DdsOptions in_b = net_;
  in_b.interface = ns.vethB();
  in_b.peers = {ns.addressA()};
  runWithRogues({ns.namespaceB(), in_b, ns.execInA(), "--interface " + ns.vethA() + " --peer " + ns.addressB()});
}

TEST_F(SecureTeleop, AcrossTwoNetworkNamespacesWithMulticastDiscoveryOnlyTheAuthenticatedSensorGetsThrough) {
  test_support::VethNamespaces ns;  // no --interface, no --peer: Cyclone DDS's own choice (the veth) and multicast
  if (const std::string why = ns.create(); !why.empty()) GTEST_SKIP() << "network namespaces unavailable here: " << why;
  dds::DdsOptions in_b = net_;
  in_b.interface.clear();
  in_b.peers.clear();
  runWithRogues({ns.namespaceB(), in_b, ns.execInA(), ""});
}

}  // namespace
