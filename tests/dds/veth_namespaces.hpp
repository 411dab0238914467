// tests/dds/veth_namespaces.hpp — two network namespaces joined by a veth
// pair ("two hosts on one machine"), created for one test and removed after
// it: A at 10.231.N.1/24, B at 10.231.N.2/24 (N from the process id), each
// with its loopback up and multicast on the veth. Nothing is routed out of
// them, so the test sees no outside traffic. create() returns an empty string
// on success, else why the namespaces cannot be made here (no privilege, no
// `ip`), for the test to skip with that message.
#pragma once

#include <string>

namespace onetip::test_support {

class VethNamespaces {
 public:
  VethNamespaces();
  ~VethNamespaces();
  VethNamespaces(const VethNamespaces&) = delete;
  VethNamespaces& operator=(const VethNamespaces&) = delete;

  std::string create();
  // Drops `percent` % of the UDP datagrams A sends to odd ports, each send
  // decided at random (nftables in A, output hook). RTPS puts user data on odd
  // ports (7400 + 250 d + 11 + 2 i) and discovery on even ones, so discovery
  // is untouched and data is lost. A datagram dropped there fails the sender's
  // sendmsg() with EPERM, which Cyclone DDS 0.10 retries twice: see
  // docs/dds/README.md for what that does to the loss rate.
  // Empty on success, else why not (no nft).
  std::string dropDataFromA(int percent);
  // What the rule saw so far: datagrams A tried to send to odd ports (every
  // attempt, retries included) and how many of them it dropped (-1, -1 when
  // the counters cannot be read).
  struct DropCounts {
    long sent = -1, dropped = -1;
  };
  DropCounts dropCountsFromA() const;
  // "ip netns exec <ns> " prefixes for a command line.
  std::string execInA() const { return "ip netns exec " + ns_a_ + " "; }
  std::string execInB() const { return "ip netns exec " + ns_b_ + " "; }
  const std::string& namespaceA() const { return ns_a_; }
  const std::string& namespaceB() const { return ns_b_; }
  const std::string& vethA() const { return veth_a_; }
  const std::string& vethB() const { return veth_b_; }
  const std::string& addressA() const { return addr_a_; }
  const std::string& addressB() const { return addr_b_; }

 private:
  std::string ns_a_, ns_b_, veth_a_, veth_b_, addr_a_, addr_b_;
  bool created_ = false;
};

}  // namespace onetip::test_support
