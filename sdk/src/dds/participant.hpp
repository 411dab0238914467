// dds/participant.hpp — one DDS domain participant (Eclipse Cyclone DDS) and
// ROS 2's topic naming, shared by every onetip publisher and subscriber.
//
// Topics follow ROS 2's DDS mapping: the ROS topic /<namespace>/<name> is the
// DDS topic "rt/<namespace>/<name>" (docs/dds/README.md lists onetip's topics).
// A namespace is one or more ROS name tokens ([A-Za-z_][A-Za-z0-9_]*) joined by
// '/', given with or without a leading '/'.
//
// Network: by default Cyclone DDS picks its interface and discovers peers by
// multicast (or reads CYCLONEDDS_URI). `interface` restricts it to one network
// interface (e.g. "lo" or a veth in a network namespace) and `peers` lists
// unicast discovery addresses (needed where the interface has no multicast,
// such as the loopback); both together make a domain that uses no other
// address.
//
// The user's CYCLONEDDS_URI is never dropped: with `interface` or `peers` the
// domain is created from "<CYCLONEDDS_URI>,<onetip's XML>", a list Cyclone
// DDS reads in order (0.10.2, verified in tests/dds/test_cyclone_uri.cpp):
// a section only the user gives (Security, Tracing, ...) is kept whole; a
// setting both give takes onetip's value (AllowMulticast); lists add up
// (the user's interfaces and peers are used beside --interface and --peer).
#pragma once

#include <dds/dds.h>

#include <string>
#include <vector>

namespace onetip::dds {

struct DdsOptions {
  int domain = 0;                  // DDS domain id, 0 .. 232 (ROS_DOMAIN_ID)
  std::string ros_namespace = "onetip";
  std::string interface;           // network interface name; empty: Cyclone's default
  std::vector<std::string> peers;  // unicast discovery peers (IPv4 addresses)
  void validate() const;           // throws InputError naming the bad field
};

// Tokens [A-Za-z_][A-Za-z0-9_]* joined by '/' (no leading '/').
bool isRosName(const std::string& name);
// The TF frame of a sensor published under `ros_namespace`: "<namespace>_sensor"
// (without a leading '/'), so two sensors in two namespaces have two frames.
std::string sensorFrameId(const std::string& ros_namespace);
// "rt/<namespace>/<name>"; InputError for a namespace or name that is not a ROS name.
std::string rosTopicName(const std::string& ros_namespace, const std::string& name);
// The Cyclone DDS configuration (XML) for `interface` and `peers`; empty when neither is set.
std::string cycloneConfig(const DdsOptions& options);
// The configuration the domain is created from: empty when onetip has none
// (Cyclone then reads CYCLONEDDS_URI itself), else `user_uri` (the value of
// CYCLONEDDS_URI; null or blank: none) followed by onetip's, comma-separated.
std::string domainConfig(const DdsOptions& options, const char* user_uri);

class Participant {
 public:
  // InputError for bad options or an interface Cyclone DDS cannot use;
  // std::runtime_error when DDS refuses otherwise (with its message).
  explicit Participant(const DdsOptions& options);
  ~Participant();
  Participant(const Participant&) = delete;
  Participant& operator=(const Participant&) = delete;

  dds_entity_t handle() const noexcept { return participant_; }
  const DdsOptions& options() const noexcept { return options_; }
  std::string topic(const std::string& name) const { return rosTopicName(options_.ros_namespace, name); }

 private:
  DdsOptions options_;
  dds_entity_t domain_ = 0;
  dds_entity_t participant_ = 0;
};

// Throws std::runtime_error("<what>: <DDS error text>") when rc < 0; returns rc.
dds_return_t checkDds(dds_return_t rc, const std::string& what);

}  // namespace onetip::dds
