#include "dds/participant.hpp"

#include <arpa/inet.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "core/error.hpp"

namespace onetip::dds {
namespace {

bool isAsciiAlpha(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool isAsciiDigit(char c) { return c >= '0' && c <= '9'; }

// [A-Za-z_][A-Za-z0-9_]*
bool isRosToken(const std::string& t) {
  return !t.empty() && (isAsciiAlpha(t[0]) || t[0] == '_') &&
         std::all_of(t.begin(), t.end(), [](char c) { return isAsciiAlpha(c) || isAsciiDigit(c) || c == '_'; });
}

// [A-Za-z0-9_.@-]{1,15} (Linux interface names are at most 15 characters)
bool isInterfaceName(const std::string& n) {
  return !n.empty() && n.size() <= 15 && std::all_of(n.begin(), n.end(), [](char c) {
    return isAsciiAlpha(c) || isAsciiDigit(c) || c == '_' || c == '.' || c == '@' || c == '-';
  });
}

std::string stripLeadingSlash(const std::string& s) { return !s.empty() && s[0] == '/' ? s.substr(1) : s; }

}  // namespace

bool isRosName(const std::string& name) {
  if (name.empty()) return false;
  size_t start = 0;
  for (;;) {
    const size_t slash = name.find('/', start);
    const std::string token = name.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
    if (!isRosToken(token)) return false;
    if (slash == std::string::npos) return true;
    start = slash + 1;
  }
}

std::string sensorFrameId(const std::string& ros_namespace) {
  return stripLeadingSlash(ros_namespace) + "_sensor";
}

void DdsOptions::validate() const {
  if (domain < 0 || domain > 232) throw InputError("dds domain " + std::to_string(domain) + ": must be 0 .. 232");
  if (!isRosName(stripLeadingSlash(ros_namespace)))
    throw InputError("dds namespace '" + ros_namespace + "': not a ROS name (tokens [A-Za-z_][A-Za-z0-9_]* joined by '/')");
  if (!interface.empty() && !isInterfaceName(interface))
    throw InputError("dds interface '" + interface + "': not a network interface name");
  for (const std::string& p : peers) {
    in_addr addr{};
    if (inet_pton(AF_INET, p.c_str(), &addr) != 1) throw InputError("dds peer '" + p + "': not an IPv4 address");
  }
}

std::string rosTopicName(const std::string& ros_namespace, const std::string& name) {
  const std::string ns = stripLeadingSlash(ros_namespace);
  if (!isRosName(ns)) throw InputError("dds namespace '" + ros_namespace + "': not a ROS name");
  if (!isRosName(name)) throw InputError("dds topic name '" + name + "': not a ROS name");
  return "rt/" + ns + "/" + name;
}

std::string cycloneConfig(const DdsOptions& options) {
  if (options.interface.empty() && options.peers.empty()) return {};
  std::string xml = "<CycloneDDS><Domain Id=\"any\"><General>";
  if (!options.interface.empty())
    xml += "<Interfaces><NetworkInterface name=\"" + options.interface + "\"/></Interfaces>";
  if (!options.peers.empty()) xml += "<AllowMulticast>false</AllowMulticast>";
  xml += "</General>";
  if (!options.peers.empty()) {
    // Fixed participant indices, so a peer's unicast discovery ports are known.
    xml += "<Discovery><ParticipantIndex>auto</ParticipantIndex><MaxAutoParticipantIndex>30</MaxAutoParticipantIndex><Peers>";
    for (const std::string& p : options.peers) xml += "<Peer Address=\"" + p + "\"/>";
    xml += "</Peers></Discovery>";
  }
  return xml + "</Domain></CycloneDDS>";
}

std::string domainConfig(const DdsOptions& options, const char* user_uri) {
  const std::string own = cycloneConfig(options);
  const std::string user = user_uri ? user_uri : "";
  if (own.empty() || user.find_first_not_of(" \t\r\n") == std::string::npos) return own;
  return user + "," + own;
}

dds_return_t checkDds(dds_return_t rc, const std::string& what) {
  if (rc < 0) throw std::runtime_error(what + ": " + dds_strretcode(rc));
  return rc;
}

Participant::Participant(const DdsOptions& options) : options_(options) {
  options_.validate();
  options_.ros_namespace = stripLeadingSlash(options_.ros_namespace);
  const auto domain = static_cast<dds_domainid_t>(options_.domain);
  const char* user_uri = std::getenv("CYCLONEDDS_URI");
  const std::string config = domainConfig(options_, user_uri);
  if (!config.empty()) {
    domain_ = dds_create_domain(domain, config.c_str());
    if (domain_ < 0) {  // almost always an interface that does not exist or has no IPv4 address, or the user's file
      const bool merged = config != cycloneConfig(options_);
      throw InputError("dds interface '" + options_.interface + "' / peers: Cyclone DDS refused the configuration (" +
                       dds_strretcode(domain_) + "); is the interface up with an IPv4 address?" +
                       (merged ? std::string(" Is CYCLONEDDS_URI='") + user_uri + "' valid?" : std::string()));
    }
  }
  participant_ = dds_create_participant(domain, nullptr, nullptr);
  if (participant_ < 0) {
    if (domain_ > 0) dds_delete(domain_);
    checkDds(participant_, "dds participant on domain " + std::to_string(options_.domain));
  }
}

Participant::~Participant() {
  dds_delete(participant_);
  if (domain_ > 0) dds_delete(domain_);
}

}  // namespace onetip::dds
