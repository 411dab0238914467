// tests/dds/test_dds_messages.cpp — the pure parts of onetip_dds: ROS time
// stamps and their system-clock mapping, the Joy axes' scaling, the pose
// quaternion against an independent construction, the marker cloud's byte
// layout, ROS names and frames, and the options' error messages.
#include <gtest/gtest.h>

#include <unistd.h>

#include <Eigen/Geometry>
#include <chrono>
#include <cstring>

#include "dds/participant.hpp"
#include "dds/ros_clock.hpp"
#include "dds/ros_messages.hpp"
#include "dds/static_transform.hpp"
#include "input_error_of.hpp"
#include "pipeline/frame_processor.hpp"

namespace {

using namespace onetip;
using onetip::test_support::inputErrorOf;

TEST(DdsMessages, RosTimeSplitsSecondsAndNanoseconds) {
  EXPECT_EQ(dds::rosTime(0.0).sec, 0);
  EXPECT_EQ(dds::rosTime(1.5).sec, 1);
  EXPECT_EQ(dds::rosTime(1.5).nanosec, 500000000u);
  const dds::RosTime t = dds::rosTime(3.9999999999);  // rounds up to the next second, never 1e9 ns
  EXPECT_EQ(t.sec, 4);
  EXPECT_EQ(t.nanosec, 0u);
  EXPECT_NEAR(dds::seconds(dds::rosTime(12345.678901234)), 12345.678901234, 1e-9);
}

// rviz2 and tf2 compare stamps with the system clock: the first frame is
// stamped with the system time of its arrival, later ones keep the source's spacing.
TEST(DdsMessages, StampsAreOnTheSystemClockWithTheSourcesSpacing) {
  dds::SourceToSystemClock clock;
  EXPECT_FALSE(clock.offset());
  EXPECT_DOUBLE_EQ(clock.stamp(2.0, 1.8e9), 1.8e9);
  EXPECT_DOUBLE_EQ(clock.stamp(2.5, 1.8e9 + 7.0), 1.8e9 + 0.5);  // the arrival of later frames does not move it
  EXPECT_DOUBLE_EQ(clock.stamp(1.0, 0.0), 1.8e9 - 1.0);
  const double system_now =
      std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  const double a_second_ago = dds::systemSecondsAt(std::chrono::steady_clock::now() - std::chrono::seconds(1));
  EXPECT_NEAR(a_second_ago, system_now - 1.0, 0.05);
}

// As spacenav_node reports a SpaceMouse: each axis over its full scale (the
// working range), clamped to [-1, 1].
TEST(DdsMessages, JoyAxesAreTheInputOverTheWorkingRangeClamped) {
  const std::array<double, 6> range{4, 4, 3, 15, 40, 40};
  const auto a = dds::joyAxes(Input6{2.0, -4.0, 1.5, 30.0, -50.0, 10.0}, range);
  const std::array<float, 6> want{0.5f, -1.0f, 0.5f, 1.0f, -1.0f, 0.25f};
  for (size_t i = 0; i < 6; ++i) EXPECT_FLOAT_EQ(a[i], want[i]) << "axis " << i;
  const auto b = dds::joyAxes(Input6{0.4, 0, 0, 0, 0, 0}, {0.8, 1, 1, 1, 1, 1});
  EXPECT_FLOAT_EQ(b[0], 0.5f);
}

TEST(DdsMessages, PoseIsTheConventionsMotionInMetresAndAUnitQuaternion) {
  const Input6 v{1.0, -2.0, 0.5, 10.0, -20.0, 30.0};
  const auto p = dds::positionMetres(v);
  EXPECT_DOUBLE_EQ(p[0], 0.001);
  EXPECT_DOUBLE_EQ(p[1], -0.002);
  EXPECT_DOUBLE_EQ(p[2], -0.0005);  // dz is positive into the pad, S.z points out of it
  const double d = M_PI / 180;
  // R = Rz(yaw) Ry(roll) Rx(pitch), built here from axis-angle rotations.
  const Eigen::Matrix3d want = (Eigen::AngleAxisd(10 * d, Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(30 * d, Eigen::Vector3d::UnitY()) *
                                Eigen::AngleAxisd(-20 * d, Eigen::Vector3d::UnitX()))
                                   .toRotationMatrix();
  const auto q = dds::quaternionXyzw(v);
  EXPECT_GE(q[3], 0.0);
  const Eigen::Quaterniond got(q[3], q[0], q[1], q[2]);
  EXPECT_NEAR(got.norm(), 1.0, 1e-12);
  EXPECT_LT((got.toRotationMatrix() - want).norm(), 1e-12);
}

TEST(DdsMessages, MarkerCloudHoldsValidMarkersWithTheirIdsLabelsAndDisplacements) {
  pipeline::FrameResult r;
  r.markers = MarkerField(2, 3);
  r.markers.position[1] = {1.0, 2.0, 3.0};
  r.markers.valid[1] = 1;
  r.markers.position[4] = {-4.0, 5.0, -6.0};
  r.markers.valid[4] = 1;
  r.pose.field.displacement.assign(6, Eigen::Vector3d::Zero());
  r.pose.field.valid.assign(6, 0);
  r.pose.field.displacement[4] = {0.3, 0.0, -0.4};
  r.pose.field.valid[4] = 1;
  r.pose.step.labels.assign(6, contact::MarkerLabel::outside);
  r.pose.step.labels[4] = contact::MarkerLabel::slip;
  const dds::MarkerCloud c = dds::markerCloud(r);
  ASSERT_EQ(c.width, 2u);
  ASSERT_EQ(c.data.size(), 2 * dds::kMarkerPointStep);
  auto f64 = [&](size_t point, size_t offset) {
    double v;
    std::memcpy(&v, c.data.data() + point * dds::kMarkerPointStep + offset, 8);
    return v;
  };
  auto u32 = [&](size_t point, size_t offset) {
    std::uint32_t v;
    std::memcpy(&v, c.data.data() + point * dds::kMarkerPointStep + offset, 4);
    return v;
  };
  EXPECT_DOUBLE_EQ(f64(0, 0), 0.001);
  EXPECT_EQ(u32(0, 32), 1u);
  EXPECT_EQ(c.data[36], 0);
  EXPECT_DOUBLE_EQ(f64(1, 16), -0.006);
  EXPECT_NEAR(f64(1, 24), 0.0005, 1e-15);  // |(0.3, 0, -0.4)| mm
  EXPECT_EQ(u32(1, 32), 4u);
  EXPECT_EQ(c.data[dds::kMarkerPointStep + 36], 2);  // slip
  for (const auto& f : dds::markerCloudFields()) EXPECT_LT(f.offset, dds::kMarkerPointStep);
}

TEST(DdsNames, TopicsFollowRos2Mapping) {
  EXPECT_EQ(dds::rosTopicName("onetip", "joy"), "rt/onetip/joy");
  EXPECT_EQ(dds::rosTopicName("/robot/left_tip", "haptic/sensed"), "rt/robot/left_tip/haptic/sensed");
  EXPECT_NE(inputErrorOf([] { dds::rosTopicName("a b", "joy"); }).find("a b"), std::string::npos);
  EXPECT_NE(inputErrorOf([] { dds::rosTopicName("ns", "2joy"); }).find("2joy"), std::string::npos);
  EXPECT_NE(inputErrorOf([] { dds::rosTopicName("ns//x", "joy"); }).find("ns//x"), std::string::npos);
}

// Two sensors in two namespaces have two TF frames; the static transform
// refuses a frame that is no ROS name, or a parent that is the sensor frame.
TEST(DdsNames, SensorFrameIsUnderTheNamespaceAndItsParentIsChecked) {
  EXPECT_EQ(dds::sensorFrameId("onetip"), "onetip_sensor");
  EXPECT_EQ(dds::sensorFrameId("/robot/left_tip"), "robot/left_tip_sensor");
  EXPECT_NE(dds::sensorFrameId("left"), dds::sensorFrameId("right"));
  dds::DdsOptions o;
  o.domain = 1 + ::getpid() % 200;
  o.interface = "lo";
  o.peers = {"127.0.0.1"};
  const dds::Participant p(o);
  EXPECT_NE(inputErrorOf([&] { dds::StaticTransformPublisher(p, "my frame", "onetip_sensor"); }).find("'my frame'"),
            std::string::npos);
  EXPECT_NE(inputErrorOf([&] { dds::StaticTransformPublisher(p, "onetip_sensor", "onetip_sensor"); }).find("itself"),
            std::string::npos);
  EXPECT_NO_THROW(dds::StaticTransformPublisher(p, "base_link", "onetip_sensor"));
}

TEST(DdsNames, BadOptionsNameTheField) {
  dds::DdsOptions o;
  o.domain = 233;
  EXPECT_NE(inputErrorOf([&] { o.validate(); }).find("domain 233"), std::string::npos);
  o = {};
  o.peers = {"10.0.0.300"};
  EXPECT_NE(inputErrorOf([&] { o.validate(); }).find("peer '10.0.0.300'"), std::string::npos);
  o = {};
  o.interface = "no such interface";
  EXPECT_NE(inputErrorOf([&] { o.validate(); }).find("interface"), std::string::npos);
  o = {};
  o.interface = "abcdefghijklmnop";  // 16 characters: Linux allows 15
  EXPECT_NE(inputErrorOf([&] { o.validate(); }).find("abcdefghijklmnop"), std::string::npos);
  o.interface = "veth-a.1@b_2345";  // 15 characters of the allowed set
  EXPECT_NO_THROW(o.validate());
  o = {};
  o.ros_namespace = "/_robot/tip2";
  EXPECT_NO_THROW(o.validate());
  for (const char* bad : {"robot/2tip", "rob\xc3\xa9t", "robot/", "robot-left"}) {
    o.ros_namespace = bad;
    EXPECT_NE(inputErrorOf([&] { o.validate(); }).find(bad), std::string::npos) << bad;
  }
  o = {};
  o.interface = "nosuchif0";
  o.peers = {"127.0.0.1"};
  EXPECT_NE(inputErrorOf([&] { dds::Participant p(o); }).find("nosuchif0"), std::string::npos);
}

TEST(DdsNames, ConfigRestrictsToTheInterfaceAndPeers) {
  dds::DdsOptions o;
  EXPECT_EQ(dds::cycloneConfig(o), "");
  o.interface = "lo";
  o.peers = {"127.0.0.1"};
  const std::string xml = dds::cycloneConfig(o);
  EXPECT_NE(xml.find("<NetworkInterface name=\"lo\"/>"), std::string::npos);
  EXPECT_NE(xml.find("<Peer Address=\"127.0.0.1\"/>"), std::string::npos);
  EXPECT_NE(xml.find("<AllowMulticast>false</AllowMulticast>"), std::string::npos);
}

}  // namespace
