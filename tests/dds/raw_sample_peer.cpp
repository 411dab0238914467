#include "raw_sample_peer.hpp"

#include <dds/ddsi/ddsi_serdata.h>
#include <dds/ddsi/ddsi_sertype.h>
#include <unistd.h>

#include <limits>
#include <stdexcept>
#include <vector>

namespace onetip::dds_test {
namespace {

// The topic's serialisation type, as Cyclone DDS 0.10 exposes it: on a
// serialized sample a reader takes. So one all-zero sample of our own goes to
// a reader of our own, made and deleted here (a later reader sees it only on a latched stream).
const ddsi_sertype* topicType(const dds::Participant& p, dds_entity_t topic, dds_entity_t writer,
                              const dds_topic_descriptor_t& type, dds::StreamKind kind) {
  const dds::QosPtr q = dds::readerQos(kind, {});
  const dds_entity_t reader = dds::checkDds(dds_create_reader(p.handle(), topic, q.get(), nullptr), "raw peer reader");
  std::vector<std::uint64_t> zero((type.m_size + sizeof(std::uint64_t) - 1) / sizeof(std::uint64_t));
  ddsi_serdata* sample = nullptr;
  dds_sample_info_t info{};
  const bool taken = dds_write(writer, zero.data()) == DDS_RETCODE_OK &&
                     dds_takecdr(reader, &sample, 1, &info, DDS_ANY_STATE) == 1;
  const ddsi_sertype* t = taken ? ddsi_sertype_ref(sample->type) : nullptr;
  if (sample) ddsi_serdata_unref(sample);
  dds_delete(reader);
  if (!t) throw std::runtime_error("raw peer: no serialized sample of " + std::string(type.m_typename));
  return t;
}

}  // namespace

dds::DdsOptions loopbackOnlyOptions() {
  dds::DdsOptions o;
  o.interface = "lo";
  o.ros_namespace = "raw_peer_" + std::to_string(::getpid());
  return o;
}

RawSamplePeer::RawSamplePeer(const dds::Participant& p, const dds_topic_descriptor_t& type,
                             const std::string& topic_name, dds::StreamKind kind) {
  topic_ = dds::checkDds(dds_create_topic(p.handle(), &type, topic_name.c_str(), nullptr, nullptr),
                         "raw peer topic " + topic_name);
  const dds::QosPtr q = dds::writerQos(kind, {});
  writer_ = dds::checkDds(dds_create_writer(p.handle(), topic_, q.get(), nullptr), "raw peer writer " + topic_name);
  type_ = topicType(p, topic_, writer_, type, kind);
}

RawSamplePeer::~RawSamplePeer() {
  ddsi_sertype_unref(const_cast<ddsi_sertype*>(type_));
  dds_delete(writer_);
  dds_delete(topic_);
}

bool RawSamplePeer::send(std::span<const std::uint8_t> payload, dds_time_t source_timestamp) {
  if (payload.size() > std::numeric_limits<ddsrt_iov_len_t>::max()) return false;
  ddsrt_iovec_t iov{};
  iov.iov_base = const_cast<std::uint8_t*>(payload.data());  // read only
  iov.iov_len = static_cast<ddsrt_iov_len_t>(payload.size());
  ddsi_serdata* sample = ddsi_serdata_from_ser_iov(type_, SDK_DATA, 1, &iov, payload.size());
  if (!sample) return false;
  sample->statusinfo = 0;
  sample->timestamp.v = source_timestamp;
  return dds_forwardcdr(writer_, sample) == DDS_RETCODE_OK;  // takes the reference
}

}  // namespace onetip::dds_test
