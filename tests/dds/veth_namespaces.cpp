#include "veth_namespaces.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace onetip::test_support {
namespace {

int sh(const std::string& cmd) { return std::system((cmd + " >/dev/null 2>&1").c_str()); }

}  // namespace

VethNamespaces::VethNamespaces() {
  const std::string id = std::to_string(::getpid());
  ns_a_ = "onetip-a-" + id;
  ns_b_ = "onetip-b-" + id;
  veth_a_ = "ota" + id;  // interface names: at most 15 characters
  veth_b_ = "otb" + id;
  const std::string net = "10.231." + std::to_string(::getpid() % 250) + ".";
  addr_a_ = net + "1";
  addr_b_ = net + "2";
}

std::string VethNamespaces::create() {
  if (sh("ip -V") != 0) return "the `ip` program (iproute2) is missing";
  if (sh("ip netns add " + ns_a_) != 0) return "cannot create a network namespace (needs root / CAP_SYS_ADMIN)";
  created_ = true;
  if (sh("ip netns add " + ns_b_) != 0) return "cannot create a second network namespace";
  const std::string a = "ip -n " + ns_a_ + " ", b = "ip -n " + ns_b_ + " ";
  const bool ok = sh(a + "link add " + veth_a_ + " type veth peer name " + veth_b_ + " netns " + ns_b_) == 0 &&
                  sh(a + "addr add " + addr_a_ + "/24 dev " + veth_a_) == 0 &&
                  sh(b + "addr add " + addr_b_ + "/24 dev " + veth_b_) == 0 && sh(a + "link set lo up") == 0 &&
                  sh(b + "link set lo up") == 0 && sh(a + "link set " + veth_a_ + " up") == 0 &&
                  sh(b + "link set " + veth_b_ + " up") == 0;
  if (!ok) return "cannot create or configure the veth pair between the namespaces";
  // The pair reports UP a moment after both ends are set up; DDS ignores a link that is down.
  for (int i = 0; i < 300; ++i) {
    if (sh(a + "link show " + veth_a_ + " | grep -q 'state UP'") == 0 &&
        sh(b + "link show " + veth_b_ + " | grep -q 'state UP'") == 0)
      return {};
    ::usleep(10000);
  }
  return "the veth pair did not come up within 3 s";
}

std::string VethNamespaces::dropDataFromA(int percent) {
  const std::string nft = "ip netns exec " + ns_a_ + " nft ";
  if (sh(nft + "add table inet onetip_loss") != 0) return "cannot add an nftables table (is nftables installed?)";
  const bool ok =
      sh(nft + "'add chain inet onetip_loss out { type filter hook output priority 0; }'") == 0 &&
      sh(nft + "'add rule inet onetip_loss out udp dport & 1 == 1 counter'") == 0 &&
      sh(nft + "'add rule inet onetip_loss out udp dport & 1 == 1 numgen random mod 100 < " + std::to_string(percent) +
         " counter drop'") == 0;
  return ok ? std::string() : "cannot add the nftables drop rule";
}

VethNamespaces::DropCounts VethNamespaces::dropCountsFromA() const {
  FILE* p = ::popen(("ip netns exec " + ns_a_ + " nft list chain inet onetip_loss out 2>/dev/null").c_str(), "r");
  if (!p) return {};
  std::string text;
  char buf[512];
  while (std::fgets(buf, sizeof buf, p)) text += buf;
  ::pclose(p);
  // The chain lists the counting rule, then the dropping rule.
  const std::string key = "counter packets ";
  const size_t first = text.find(key);
  const size_t second = first == std::string::npos ? first : text.find(key, first + key.size());
  if (second == std::string::npos) return {};
  return {std::stol(text.substr(first + key.size())), std::stol(text.substr(second + key.size()))};
}

VethNamespaces::~VethNamespaces() {
  if (!created_) return;
  sh("ip netns del " + ns_a_);  // removes veth_a, and with it its peer
  sh("ip netns del " + ns_b_);
}

}  // namespace onetip::test_support
