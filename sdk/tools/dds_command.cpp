#include "dds_command.hpp"

#include <sstream>

namespace onetip::tools {

std::vector<OptionSpec> ddsOptionSpecs() {
  return {{"domain", "DDS domain id, 0 .. 232 (as ROS_DOMAIN_ID; default 0)", false, false},
          {"namespace", "ROS namespace of the topics, rt/<namespace>/... (default onetip)", false, false},
          {"interface", "network interface to use only (e.g. lo); default: Cyclone DDS's choice", false, false},
          {"peer", "unicast discovery peers, comma-separated IPv4 addresses (e.g. 127.0.0.1)", false, false}};
}

dds::DdsOptions ddsOptionsFromArgs(const Args& args) {
  dds::DdsOptions o;
  o.domain = args.getInt("domain", 0);
  o.ros_namespace = args.optional("namespace").value_or(o.ros_namespace);
  o.interface = args.optional("interface").value_or("");
  if (auto peers = args.optional("peer")) {
    std::stringstream ss(*peers);
    for (std::string p; std::getline(ss, p, ',');) o.peers.push_back(p);
  }
  o.validate();
  return o;
}

}  // namespace onetip::tools
