// tests/dds/test_cyclone_uri.cpp — the user's CYCLONEDDS_URI survives
// --interface and --peer (dds/participant.hpp): the domain onetip creates
// from its own XML is given the user's configuration first. Observed through
// a setting with a visible effect: the user's Tracing section, which makes
// Cyclone DDS write its effective configuration to a file the test names.
// The trace then also shows that onetip's own settings held (its peer).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "dds/participant.hpp"
#include "input_error_of.hpp"
#include "scoped_env.hpp"
#include "scratch_dir.hpp"

namespace {

using namespace onetip;
using onetip::test_support::inputErrorOf;
using onetip::test_support::ScopedEnv;

dds::DdsOptions loopback() {
  dds::DdsOptions o;
  o.domain = 1 + ::getpid() % 200;
  o.interface = "lo";
  o.peers = {"127.0.0.1"};
  return o;
}

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(DdsNames, DomainConfigPutsTheUsersUriBeforeOnetips) {
  const dds::DdsOptions o = loopback();
  const std::string own = dds::cycloneConfig(o);
  EXPECT_EQ(dds::domainConfig(o, nullptr), own);
  EXPECT_EQ(dds::domainConfig(o, " \t"), own);
  EXPECT_EQ(dds::domainConfig(o, "file:///etc/dds.xml"), "file:///etc/dds.xml," + own);
  EXPECT_EQ(dds::domainConfig(dds::DdsOptions{}, "file:///etc/dds.xml"), "")
      << "without --interface or --peer Cyclone DDS reads CYCLONEDDS_URI itself";
}

TEST(CycloneUri, UsersSectionIsInEffectWithInterfaceAndPeer) {
  test_support::ScratchDir dir("onetip-cyclone-uri");
  const std::string trace = dir.file("cyclone-trace.log");
  const std::string user = "<CycloneDDS><Domain Id=\"any\"><Tracing><Verbosity>config</Verbosity><OutputFile>" + trace +
                           "</OutputFile></Tracing></Domain></CycloneDDS>";
  {
    const ScopedEnv env("CYCLONEDDS_URI", "file://" + dir.file("user.xml"));
    std::ofstream(dir.file("user.xml")) << user;
    dds::Participant participant(loopback());
  }
  const std::string text = readFile(trace);
  ASSERT_FALSE(text.empty()) << "the user's Tracing section was not in effect: no trace at " << trace;
  EXPECT_NE(text.find("Domain/Tracing/OutputFile/#text: " + trace), std::string::npos) << text;
  EXPECT_NE(text.find("Domain/Discovery/Peers/Peer[@Address]: 127.0.0.1"), std::string::npos) << "onetip's peer lost";
  EXPECT_NE(text.find("selected interfaces: lo"), std::string::npos) << "onetip's interface lost";
}

TEST(CycloneUri, InvalidUserUriIsNamedInTheError) {
  const ScopedEnv env("CYCLONEDDS_URI", "file:///nonexistent/onetip-cyclone.xml");
  const std::string message = inputErrorOf([] { dds::Participant p(loopback()); });
  EXPECT_NE(message.find("CYCLONEDDS_URI='file:///nonexistent/onetip-cyclone.xml'"), std::string::npos) << message;
}

}  // namespace
