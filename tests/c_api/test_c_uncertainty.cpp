// The C ABI's uncertainty (minor version 2, onetip_c_uncertainty.h) from C++:
// the structs of minor version 1 keep their size and layout; the *_sd structs
// hold them first; what the *_sd callbacks and polls give equals, frame by
// frame, the C++ API's Event::sd, FrameResult::sd and
// MarkerState::stick_probability for the same scenario; bad arguments get
// the error codes of the other functions; and (with the estimator's
// uncertainty) frames in contact carry positive deviations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "onetip/sensor.hpp"
#include "onetip_c.h"
#include "test_paths.hpp"

namespace {

const std::string kScenario = std::string(onetip::test::sourceDir()) + "/samples/scenarios/press.yaml";

// The sizes of minor version 1 (commit f85e83c): callers built against that header allocate these.
static_assert(sizeof(onetip_event) == 240 && sizeof(onetip_frame) == 384 && sizeof(onetip_marker) == 64);
static_assert(offsetof(onetip_event, message) == 80 && offsetof(onetip_frame, raw) == 64);
static_assert(offsetof(onetip_event_sd, event) == 0 && offsetof(onetip_event_sd, sd) == sizeof(onetip_event));
static_assert(offsetof(onetip_frame_sd, frame) == 0 && offsetof(onetip_frame_sd, sd) == sizeof(onetip_frame));
static_assert(offsetof(onetip_marker_sd, marker) == 0 &&
              offsetof(onetip_marker_sd, stick_probability) == sizeof(onetip_marker));

struct CRun {
  std::vector<onetip_event_sd> events;
  std::map<std::int64_t, onetip_frame_sd> frames;
  std::map<std::int64_t, std::vector<onetip_marker_sd>> markers;
};

void onEvent(const onetip_event_sd* e, void* user) { static_cast<CRun*>(user)->events.push_back(*e); }
void onFrame(const onetip_frame_sd* f, const onetip_marker_sd* m, int32_t n, void* user) {
  auto* run = static_cast<CRun*>(user);
  run->frames[f->frame.frame] = *f;
  run->markers[f->frame.frame].assign(m, m + n);
}

struct CppRun {
  std::vector<onetip::Event> events;
  std::map<std::int64_t, onetip::FrameResult> frames;
};

// The scenario through the C++ API and through the C ABI's *_sd callbacks, both lossless.
class CUncertainty : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    onetip::SensorOptions o;
    o.lossless = true;
    o.event_queue_capacity = 100000;
    onetip::Sensor sensor(onetip::SensorConfig("sim:" + kScenario, "", "", ""), o);
    sensor.onFrame([](const onetip::FrameResult& f) { cpp_.frames[f.frame] = f; });
    sensor.start();
    ASSERT_TRUE(sensor.waitFinished(240));
    for (onetip::Event e; sensor.pollEvent(e);) cpp_.events.push_back(e);

    onetip_error err;
    onetip_options options;
    ASSERT_EQ(onetip_options_default(ONETIP_C_ABI_VERSION, &options, &err), ONETIP_OK) << err.message;
    options.lossless = 1;
    options.event_queue_capacity = 100000;
    options.frame_queue_capacity = 1000;
    onetip_sensor* s = nullptr;
    const std::string source = "sim:" + kScenario;
    ASSERT_EQ(onetip_sensor_create(ONETIP_C_ABI_VERSION, source.c_str(), nullptr, nullptr, nullptr, &options, &s, &err),
              ONETIP_OK)
        << err.message;
    ASSERT_EQ(onetip_sensor_set_event_sd_callback(s, onEvent, &c_, &err), ONETIP_OK) << err.message;
    ASSERT_EQ(onetip_sensor_set_frame_sd_callback(s, onFrame, &c_, &err), ONETIP_OK) << err.message;
    ASSERT_EQ(onetip_sensor_start(s, &err), ONETIP_OK) << err.message;
    int32_t finished = 0, got = 0;
    ASSERT_EQ(onetip_sensor_wait_finished(s, 240, &finished, &err), ONETIP_OK) << err.message;
    // The poll queues hold the same values as the callbacks saw.
    for (onetip_event_sd e; onetip_sensor_poll_event_sd(s, &e, &got, &err) == ONETIP_OK && got;)
      polled_events_.push_back(e);
    std::vector<onetip_marker_sd> m(4096);
    int32_t count = 0;
    for (onetip_frame_sd f; onetip_sensor_poll_frame_sd(s, &f, m.data(), static_cast<int32_t>(m.size()), &count, &got,
                                                        &err) == ONETIP_OK &&
                            got;) {
      polled_frames_[f.frame.frame] = f;
      polled_markers_[f.frame.frame].assign(m.begin(), m.begin() + std::min<std::ptrdiff_t>(count, std::ssize(m)));
    }
    ASSERT_EQ(onetip_sensor_destroy(s, &err), ONETIP_OK) << err.message;
  }

  static void expectSd(const double (&c)[6], const onetip::Input6& cpp, const std::string& what) {
    const auto v = cpp.asArray();
    for (size_t k = 0; k < 6; ++k) EXPECT_EQ(c[k], v[k]) << what << " axis " << k;
  }

  static CppRun cpp_;
  static CRun c_;
  static std::vector<onetip_event_sd> polled_events_;
  static std::map<std::int64_t, onetip_frame_sd> polled_frames_;
  static std::map<std::int64_t, std::vector<onetip_marker_sd>> polled_markers_;
};
CppRun CUncertainty::cpp_;
CRun CUncertainty::c_;
std::vector<onetip_event_sd> CUncertainty::polled_events_;
std::map<std::int64_t, onetip_frame_sd> CUncertainty::polled_frames_;
std::map<std::int64_t, std::vector<onetip_marker_sd>> CUncertainty::polled_markers_;

TEST_F(CUncertainty, TheLibraryHasMinorVersionTwo) {
  EXPECT_GE(onetip_abi_minor_version(), 2u);
  EXPECT_EQ(ONETIP_C_ABI_MINOR_VERSION, 2u);
}

TEST_F(CUncertainty, EventsCarryTheSdOfTheCppApi) {
  ASSERT_EQ(c_.events.size(), cpp_.events.size());
  ASSERT_GT(c_.events.size(), 10u);
  for (size_t i = 0; i < c_.events.size(); ++i) {
    const onetip_event_sd& c = c_.events[i];
    const onetip::Event& e = cpp_.events[i];
    ASSERT_EQ(c.event.frame, e.frame);
    ASSERT_EQ(c.event.type, static_cast<int32_t>(e.type));
    expectSd(c.event.input, e.input, "event " + std::to_string(i) + " input");
    expectSd(c.sd, e.sd, "event " + std::to_string(i) + " sd");
  }
  ASSERT_EQ(polled_events_.size(), c_.events.size());
  for (size_t i = 0; i < c_.events.size(); ++i)
    EXPECT_EQ(std::memcmp(&polled_events_[i], &c_.events[i], sizeof(onetip_event_sd)), 0) << "event " << i;
}

TEST_F(CUncertainty, FramesAndMarkersCarryTheSdAndStickProbabilityOfTheCppApi) {
  ASSERT_EQ(c_.frames.size(), cpp_.frames.size());
  int contact = 0;
  for (const auto& [frame, f] : cpp_.frames) {
    SCOPED_TRACE("frame " + std::to_string(frame));
    ASSERT_TRUE(c_.frames.count(frame));
    const onetip_frame_sd& c = c_.frames[frame];
    EXPECT_EQ(c.frame.contact, f.contact ? 1 : 0);
    contact += f.contact;
    expectSd(c.frame.raw, f.raw, "raw");
    expectSd(c.sd, f.sd, "sd");
    const auto& markers = c_.markers[frame];
    ASSERT_EQ(markers.size(), f.markers.size());
    for (size_t id = 0; id < markers.size(); ++id) {
      EXPECT_EQ(markers[id].marker.id, static_cast<int32_t>(id));
      EXPECT_EQ(markers[id].marker.valid, f.markers[id].valid ? 1 : 0);
      EXPECT_EQ(markers[id].stick_probability, f.markers[id].stick_probability) << "marker " << id;
    }
  }
  EXPECT_GT(contact, 20);
  // The poll queue (capacity 1000, lossless) holds every frame, equal to what the callback saw.
  ASSERT_EQ(polled_frames_.size(), c_.frames.size());
  for (const auto& [frame, f] : polled_frames_) {
    EXPECT_EQ(std::memcmp(&f, &c_.frames[frame], sizeof f), 0) << "frame " << frame;
    const auto& a = polled_markers_[frame];
    const auto& b = c_.markers[frame];
    ASSERT_EQ(a.size(), b.size()) << "frame " << frame;
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(onetip_marker_sd)), 0) << "frame " << frame;
  }
}

TEST_F(CUncertainty, BadArgumentsGetTheErrorCodesOfTheOtherFunctions) {
  onetip_error err;
  onetip_event_sd e;
  onetip_frame_sd f;
  onetip_marker_sd m;
  int32_t got = 7, count = 7;
  EXPECT_EQ(onetip_sensor_poll_event_sd(nullptr, &e, &got, &err), ONETIP_ERROR_NULL_ARGUMENT);
  EXPECT_EQ(got, 0);
  EXPECT_EQ(onetip_sensor_set_event_sd_callback(nullptr, onEvent, nullptr, &err), ONETIP_ERROR_NULL_ARGUMENT);
  EXPECT_EQ(onetip_sensor_set_frame_sd_callback(nullptr, onFrame, nullptr, nullptr), ONETIP_ERROR_NULL_ARGUMENT);
  auto* made_up = reinterpret_cast<onetip_sensor*>(0x12345);
  EXPECT_EQ(onetip_sensor_poll_frame_sd(made_up, &f, &m, 1, &count, &got, &err), ONETIP_ERROR_INVALID_HANDLE);
  EXPECT_EQ(count, 0);

  onetip_sensor* s = nullptr;
  const std::string source = "sim:" + kScenario;
  ASSERT_EQ(onetip_sensor_create(ONETIP_C_ABI_VERSION, source.c_str(), nullptr, nullptr, nullptr, nullptr, &s, &err),
            ONETIP_OK);
  EXPECT_EQ(onetip_sensor_poll_event_sd(s, nullptr, &got, &err), ONETIP_ERROR_NULL_ARGUMENT);
  EXPECT_NE(std::string(err.message).find("onetip_sensor_poll_event_sd: out"), std::string::npos) << err.message;
  EXPECT_EQ(onetip_sensor_poll_event_sd(s, &e, nullptr, &err), ONETIP_ERROR_NULL_ARGUMENT);
  EXPECT_EQ(onetip_sensor_wait_event_sd(s, NAN, &e, &got, &err), ONETIP_ERROR_INPUT);
  EXPECT_EQ(onetip_sensor_wait_event_sd(s, 0.01, &e, &got, &err), ONETIP_OK);  // before start: returns, nothing taken
  EXPECT_EQ(got, 0);
  EXPECT_EQ(onetip_sensor_poll_frame_sd(s, &f, &m, -1, &count, &got, &err), ONETIP_ERROR_INPUT);
  EXPECT_EQ(onetip_sensor_poll_frame_sd(s, &f, nullptr, 1, &count, &got, &err), ONETIP_ERROR_NULL_ARGUMENT);
  EXPECT_EQ(onetip_sensor_poll_frame_sd(s, &f, nullptr, 0, nullptr, &got, &err), ONETIP_ERROR_NULL_ARGUMENT);
  EXPECT_EQ(onetip_sensor_poll_frame_sd(s, &f, nullptr, 0, &count, &got, &err), ONETIP_OK);
  EXPECT_EQ(onetip_sensor_set_event_sd_callback(s, nullptr, nullptr, &err), ONETIP_OK);  // NULL removes it
  ASSERT_EQ(onetip_sensor_destroy(s, &err), ONETIP_OK);
  EXPECT_EQ(onetip_sensor_poll_event_sd(s, &e, &got, &err), ONETIP_ERROR_INVALID_HANDLE);
  EXPECT_EQ(onetip_sensor_wait_event_sd(s, 0, &e, &got, &err), ONETIP_ERROR_INVALID_HANDLE);
  EXPECT_EQ(onetip_sensor_set_frame_sd_callback(s, onFrame, nullptr, &err), ONETIP_ERROR_INVALID_HANDLE);
}

// Frames in contact carry a positive sd on every axis (but the onset, where
// the input is zero by definition and its sd 0) and some sticking marker.
TEST_F(CUncertainty, FramesInContactHavePositiveSdAndStickingMarkers) {
  int contact = 0;
  bool was_in_contact = false;
  for (const auto& [frame, f] : c_.frames) {
    const bool onset = f.frame.contact && !was_in_contact;
    was_in_contact = f.frame.contact != 0;
    if (!f.frame.contact) {
      for (double sd : f.sd) EXPECT_EQ(sd, 0.0) << "frame " << frame << " out of contact";
      continue;
    }
    ++contact;
    for (double sd : f.sd) {
      if (onset) EXPECT_EQ(sd, 0.0) << "frame " << frame << ": the onset";
      else EXPECT_GT(sd, 0.0) << "frame " << frame;
    }
    double most = 0;
    for (const onetip_marker_sd& m : c_.markers[frame]) {
      EXPECT_GE(m.stick_probability, 0.0);
      EXPECT_LE(m.stick_probability, 1.0);
      most = std::max(most, m.stick_probability);
    }
    EXPECT_GT(most, 0.0) << "frame " << frame << ": no marker of the pressing finger sticks";
  }
  EXPECT_GT(contact, 20);
}

}  // namespace
