#include "dds/endpoint.hpp"

#include <dds/ddsi/ddsi_serdata.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace onetip::dds {
namespace {

// Plain XCDR1, big or little endian: the first two bytes of the encapsulation (RTPS 2.3, 10.5).
bool isXcdr1(ddsi_serdata* sample) {
  std::array<unsigned char, 2> id{};
  ddsi_serdata_to_ser(sample, 0, id.size(), id.data());
  return id[0] == 0 && (id[1] == 0 || id[1] == 1);
}

// The serialized samples dds_takecdr gave, released however take() ends.
struct TakenSamples {
  std::vector<ddsi_serdata*> samples;
  int n = 0;
  ~TakenSamples() {
    for (int i = 0; i < n; ++i) ddsi_serdata_unref(samples[static_cast<size_t>(i)]);
  }
};

// One decoded sample of `type`, its contents freed at the end.
class DecodedSample {
 public:
  DecodedSample(const dds_topic_descriptor_t& type, ddsi_serdata* serialized)
      : type_(type), memory_((type.m_size + sizeof(std::uint64_t) - 1) / sizeof(std::uint64_t)) {
    ddsi_serdata_to_sample(serialized, memory_.data(), nullptr, nullptr);
  }
  ~DecodedSample() { dds_sample_free(memory_.data(), &type_, DDS_FREE_CONTENTS); }
  DecodedSample(const DecodedSample&) = delete;
  DecodedSample& operator=(const DecodedSample&) = delete;
  const void* get() const noexcept { return memory_.data(); }

 private:
  const dds_topic_descriptor_t& type_;
  // Zeroed (the decoder allocates the contents), in 8-byte words: the IDL types hold nothing wider. Not
  // max_align_t: its long double has padding that value-initialisation leaves as it was.
  std::vector<std::uint64_t> memory_;
};

dds_entity_t makeTopic(const Participant& p, const dds_topic_descriptor_t& type, const std::string& name) {
  return checkDds(dds_create_topic(p.handle(), &type, name.c_str(), nullptr, nullptr), "dds topic " + name);
}

}  // namespace

Writer::Writer(const Participant& participant, const dds_topic_descriptor_t& type, const std::string& topic_name,
               StreamKind kind, const StreamQos& qos)
    : name_(topic_name) {
  topic_ = makeTopic(participant, type, name_);
  const QosPtr q = writerQos(kind, qos);
  writer_ = dds_create_writer(participant.handle(), topic_, q.get(), nullptr);
  if (writer_ < 0) {
    dds_delete(topic_);
    checkDds(writer_, "dds writer on " + name_);
  }
}

Writer::~Writer() {
  dds_delete(writer_);
  dds_delete(topic_);
}

void Writer::write(const void* sample) { checkDds(dds_write(writer_, sample), "dds write on " + name_); }

int Writer::matchedReaders() const {
  dds_publication_matched_status_t s{};
  checkDds(dds_get_publication_matched_status(writer_, &s), "dds matched status of " + name_);
  return static_cast<int>(s.current_count);
}

Reader::Reader(const Participant& participant, const dds_topic_descriptor_t& type, const std::string& topic_name,
               StreamKind kind, const StreamQos& qos, double requested_deadline_s,
               std::optional<dds_topic_filter> filter)
    : name_(topic_name), type_(type) {
  topic_ = makeTopic(participant, type, name_);
  if (filter) {
    if (const dds_return_t rc = dds_set_topic_filter_extended(topic_, &*filter); rc < 0) {
      dds_delete(topic_);
      checkDds(rc, "dds topic filter on " + name_);
    }
  }
  const QosPtr q = readerQos(kind, qos, requested_deadline_s);
  reader_ = dds_create_reader(participant.handle(), topic_, q.get(), nullptr);
  if (reader_ < 0) {
    dds_delete(topic_);
    checkDds(reader_, "dds reader on " + name_);
  }
  waitset_ = checkDds(dds_create_waitset(participant.handle()), "dds waitset for " + name_);
  condition_ = checkDds(dds_create_readcondition(reader_, DDS_ANY_STATE), "dds read condition for " + name_);
  checkDds(dds_waitset_attach(waitset_, condition_, reader_), "dds waitset attach for " + name_);
}

Reader::~Reader() {
  dds_waitset_detach(waitset_, condition_);
  dds_delete(condition_);
  dds_delete(waitset_);
  dds_delete(reader_);
  dds_delete(topic_);
}

int Reader::take(const Visit& visit, int max) {
  TakenSamples taken;
  taken.samples.assign(static_cast<size_t>(max), nullptr);
  std::vector<dds_sample_info_t> infos(static_cast<size_t>(max));
  taken.n = checkDds(dds_takecdr(reader_, taken.samples.data(), static_cast<uint32_t>(max), infos.data(), DDS_ANY_STATE),
                     "dds take on " + name_);
  int visited = 0;
  for (size_t i = 0; i < static_cast<size_t>(taken.n); ++i) {
    if (!infos[i].valid_data) continue;
    ++visited;
    if (!isXcdr1(taken.samples[i])) {
      ++undecodable_;
      visit(nullptr, infos[i]);
      continue;
    }
    const DecodedSample sample(type_, taken.samples[i]);
    visit(sample.get(), infos[i]);
  }
  return visited;
}

bool Reader::waitForData(double timeout_s) {
  return checkDds(dds_waitset_wait(waitset_, nullptr, 0, toDuration(timeout_s)), "dds wait on " + name_) > 0;
}

int Reader::matchedWriters() const {
  dds_subscription_matched_status_t s{};
  checkDds(dds_get_subscription_matched_status(reader_, &s), "dds matched status of " + name_);
  return static_cast<int>(s.current_count);
}

int Reader::aliveWriters() const {
  dds_liveliness_changed_status_t s{};
  checkDds(dds_get_liveliness_changed_status(reader_, &s), "dds liveliness of " + name_);
  return static_cast<int>(s.alive_count);
}

std::string Reader::writerGuid(dds_instance_handle_t writer) const {
  dds_builtintopic_endpoint_t* e = dds_get_matched_publication_data(reader_, writer);
  if (!e) return "unknown";
  std::string guid;
  char word[9];
  for (size_t w = 0; w < 4; ++w) {
    const unsigned char* b = e->key.v + 4 * w;
    std::snprintf(word, sizeof word, "%x", static_cast<unsigned>(b[0] << 24 | b[1] << 16 | b[2] << 8 | b[3]));
    guid += (w ? ":" : "") + std::string(word);
  }
  dds_builtintopic_free_endpoint(e);
  return guid;
}

}  // namespace onetip::dds
