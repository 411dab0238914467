#include "dds/stream_qos.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace onetip::dds {
namespace {

void positive(double v, const char* name) {
  if (!(v > 0)) throw InputError(std::string("dds qos ") + name + ": must be > 0 (got " + std::to_string(v) + ")");
}

QosPtr common(StreamKind kind, const StreamQos& q) {
  q.validate();
  QosPtr qos(dds_create_qos(), dds_delete_qos);
  dds_qset_durability(qos.get(), kind == StreamKind::latched ? DDS_DURABILITY_TRANSIENT_LOCAL : DDS_DURABILITY_VOLATILE);
  dds_qset_liveliness(qos.get(), DDS_LIVELINESS_AUTOMATIC, toDuration(q.lease_s));
  if (kind == StreamKind::high_rate) {
    dds_qset_reliability(qos.get(), DDS_RELIABILITY_BEST_EFFORT, 0);
    dds_qset_history(qos.get(), DDS_HISTORY_KEEP_LAST, 1);
  } else if (kind == StreamKind::latched) {
    dds_qset_reliability(qos.get(), DDS_RELIABILITY_RELIABLE, toDuration(q.max_blocking_s));
    dds_qset_history(qos.get(), DDS_HISTORY_KEEP_LAST, 1);
  } else {
    dds_qset_reliability(qos.get(), DDS_RELIABILITY_RELIABLE, toDuration(q.max_blocking_s));
    dds_qset_history(qos.get(), DDS_HISTORY_KEEP_LAST, q.event_history);
  }
  return qos;
}

}  // namespace

void StreamQos::validate() const {
  positive(deadline_s, "deadline_s");
  positive(lease_s, "lease_s");
  positive(max_blocking_s, "max_blocking_s");
  if (event_history < 1 || event_history > 100000)
    throw InputError("dds qos event_history: must be 1 .. 100000 (got " + std::to_string(event_history) + ")");
  if (reader_history < 1 || reader_history > 100000)
    throw InputError("dds qos reader_history: must be 1 .. 100000 (got " + std::to_string(reader_history) + ")");
}

dds_duration_t toDuration(double seconds) {
  if (std::isinf(seconds)) return DDS_INFINITY;
  return static_cast<dds_duration_t>(std::llround(seconds * 1e9));
}

QosPtr writerQos(StreamKind kind, const StreamQos& q) {
  QosPtr qos = common(kind, q);
  if (kind == StreamKind::high_rate) dds_qset_deadline(qos.get(), toDuration(q.deadline_s));
  return qos;
}

QosPtr readerQos(StreamKind kind, const StreamQos& q, double requested_deadline_s) {
  QosPtr qos = common(kind, q);
  positive(requested_deadline_s, "requested deadline");
  // A reader's liveliness lease must be at least the writer's offer: accept any.
  dds_qset_liveliness(qos.get(), DDS_LIVELINESS_AUTOMATIC, DDS_INFINITY);
  dds_qset_deadline(qos.get(), toDuration(requested_deadline_s));
  if (kind == StreamKind::high_rate) dds_qset_history(qos.get(), DDS_HISTORY_KEEP_LAST, q.reader_history);
  return qos;
}

}  // namespace onetip::dds
