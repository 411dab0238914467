// dds/stream_qos.hpp — the QoS of each kind of onetip stream (docs/dds/README.md).
//
//   high_rate (joy, pose, markers, haptic/sensed): BEST_EFFORT, KEEP_LAST 1,
//       VOLATILE. A late sample is worth less than the next one, so nothing is
//       resent or queued. A high-rate reader keeps `reader_history` samples
//       instead of one: its taker takes them all and uses the newest of the
//       writer it follows (dds/writer_follower.hpp), and until it has chosen,
//       one slot shared by every writer would let one writer's samples
//       overwrite another's before they are seen (two writers at the same rate
//       in step can hide one of them for good). The writer offers a DEADLINE of `deadline_s` (a
//       reader may request that or longer, and is told when the period passes
//       without a sample) and AUTOMATIC LIVELINESS with `lease_s`, so readers
//       learn within that time that the publishing process is gone.
//   events (contact begin/end, press/release, state changes, errors):
//       RELIABLE (a writer blocks at most max_blocking_s on a full queue),
//       KEEP_LAST `event_history`, VOLATILE, the same liveliness; no deadline
//       (events are sporadic).
//   latched (tf_static): RELIABLE, KEEP_LAST 1, TRANSIENT_LOCAL: the writer
//       keeps its last sample and gives it to every reader that matches later
//       (a reader must ask for transient local durability to get it), the
//       same liveliness; what ROS 2's static transform broadcaster uses.
// ROS 2 equivalents: high_rate is rclcpp::SensorDataQoS() (ROS 2 subscribers
// must ask for best effort, e.g. `ros2 topic echo --qos-reliability best_effort`);
// events is the default reliable profile with a deeper history.
#pragma once

#include <dds/dds.h>

#include <limits>
#include <memory>

namespace onetip::dds {

enum class StreamKind { high_rate, events, latched };

struct StreamQos {
  double deadline_s = 0.1;       // offered by high-rate writers
  double lease_s = 0.5;          // automatic liveliness lease
  int event_history = 256;       // events: samples kept per writer / reader
  int reader_history = 64;       // high-rate readers: samples kept between two takes, [1, 100000]
  double max_blocking_s = 0.1;   // events: reliable write blocking limit
  void validate() const;         // throws InputError naming the bad field
};

using QosPtr = std::unique_ptr<dds_qos_t, void (*)(dds_qos_t*)>;

QosPtr writerQos(StreamKind kind, const StreamQos& q);
// requested_deadline_s: what the reader asks for (infinite: no deadline); must
// be >= the writer's offer for the two to match.
QosPtr readerQos(StreamKind kind, const StreamQos& q,
                 double requested_deadline_s = std::numeric_limits<double>::infinity());
dds_duration_t toDuration(double seconds);  // DDS_INFINITY for infinity

}  // namespace onetip::dds
