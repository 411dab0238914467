#include <gtest/gtest.h>

#include "contact/contact_analyzer.hpp"
#include "core/error.hpp"
#include "synthetic_field.hpp"

using namespace onetip;
using contact::ContactAnalyzer;
using contact::ContactAnalyzerOptions;

TEST(ContactAnalyzer, RegionIsTheMarkersAboveTheCut) {
  const MarkerField rest = synth::flatGrid(17, 17);
  const auto u = synth::dimple(1.0, 2.5);
  const contact::ContactField cf = ContactAnalyzer().analyze(synth::deformed(rest, u), rest);
  ASSERT_TRUE(cf.in_contact);
  ASSERT_EQ(cf.regions.size(), 1u);
  EXPECT_NEAR(cf.max_normal_mm, 1.0, 1e-12);
  // Independent answer: normal deformation >= 40% of the peak.
  for (int i = 0; i < rest.size(); ++i) {
    const bool expected = -u(rest.position[static_cast<size_t>(i)]).z() >= 0.4;
    EXPECT_EQ(cf.inRegion(i), expected) << "marker " << i;
  }
  EXPECT_NEAR(cf.regions[0].rest_centroid.norm(), 0, 1e-9);
  EXPECT_NEAR(cf.regions[0].footprint_centre.head<2>().norm(), 0, 1e-9);
}

TEST(ContactAnalyzer, PaperRuleUsesTheModulus) {
  const MarkerField rest = synth::flatGrid(17, 17);
  ContactAnalyzerOptions o;
  o.region_measure = contact::RegionMeasure::modulus;
  o.region_fraction = 0.5;
  // Normal dimple plus a uniform tangential shift of 0.3 mm inside r < 4 mm.
  auto u = [](const Eigen::Vector3d& p) {
    Eigen::Vector3d d = synth::dimple(1.0, 2.5)(p);
    if (p.head<2>().norm() < 4.0) d.x() += 0.3;
    return d;
  };
  const contact::ContactField cf = ContactAnalyzer(o).analyze(synth::deformed(rest, u), rest);
  for (int i = 0; i < rest.size(); ++i)
    EXPECT_EQ(cf.inRegion(i), u(rest.position[static_cast<size_t>(i)]).norm() >= 0.5) << "marker " << i;
}

TEST(ContactAnalyzer, TwoFingersGiveTwoRegions) {
  const MarkerField rest = synth::flatGrid(17, 17);
  auto u = [](const Eigen::Vector3d& p) {
    return Eigen::Vector3d(synth::dimple(1.0, 1.8, -5, 0)(p) + synth::dimple(0.8, 1.8, 5, 1)(p));
  };
  const contact::ContactField cf = ContactAnalyzer().analyze(synth::deformed(rest, u), rest);
  ASSERT_EQ(cf.regions.size(), 2u);
  EXPECT_LT(cf.regions[0].rest_centroid.x(), -3.5);  // the deeper (larger) one first
  EXPECT_GT(cf.regions[1].rest_centroid.x(), 3.5);
}

TEST(ContactAnalyzer, TwoFingersWhoseImprintsJoinAreStillTwoRegions) {
  // 6 mm apart: the deformation between them stays above the 40 % cut, so the
  // markers above it form one connected area (checked below); the valley splits it.
  const MarkerField rest = synth::flatGrid(17, 17);
  auto u = [](const Eigen::Vector3d& p) {
    return Eigen::Vector3d(synth::dimple(1.0, 2.5, -3, 0)(p) + synth::dimple(0.8, 2.5, 3, 0)(p));
  };
  EXPECT_GT(-u(Eigen::Vector3d(0, 0, 0)).z(), 0.4);  // the valley is above the cut
  const contact::ContactField cf = ContactAnalyzer().analyze(synth::deformed(rest, u), rest);
  ASSERT_EQ(cf.regions.size(), 2u);
  for (int id : cf.regions[0].markers) EXPECT_LT(rest.position[static_cast<size_t>(id)].x(), 1.3) << id;
  for (int id : cf.regions[1].markers) EXPECT_GT(rest.position[static_cast<size_t>(id)].x(), -1.3) << id;
  EXPECT_LT(cf.regions[0].footprint_centre.x(), -2.0);
  EXPECT_GT(cf.regions[1].footprint_centre.x(), 2.0);
}

TEST(ContactAnalyzer, BelowTheThresholdThereIsNoContact) {
  const MarkerField rest = synth::flatGrid(17, 17);
  const contact::ContactField cf = ContactAnalyzer().analyze(synth::deformed(rest, synth::dimple(0.09, 2.5)), rest);
  EXPECT_FALSE(cf.in_contact);
  EXPECT_TRUE(cf.regions.empty());
  EXPECT_EQ(cf.status, contact::ContactFieldStatus::ok);
}

TEST(ContactAnalyzer, OneMarkerPastTheThresholdIsAContact) {
  // A fingertip between the markers of a coarse pattern (11 x 11 over 19.2 mm)
  // pushes only the nearest one past the region cut: its largest deformation
  // (0.3 mm) exceeds the 0.1 mm threshold, so the pad is in contact, its
  // region that one marker (the neighbours, 1.92 mm away, move 0.003 mm).
  const MarkerField rest = synth::flatGrid(11, 11, 1.92);
  const contact::ContactField cf = ContactAnalyzer().analyze(synth::deformed(rest, synth::dimple(0.3, 0.9)), rest);
  ASSERT_TRUE(cf.in_contact);
  ASSERT_EQ(cf.regions.size(), 1u);
  ASSERT_EQ(cf.regions[0].markers.size(), 1u);
  EXPECT_EQ(cf.regions[0].markers[0], 5 * 11 + 5);  // the centre marker, at the dimple's apex
  // Asking for two-marker regions drops it (and with it the contact).
  ContactAnalyzerOptions two;
  two.min_region_markers = 2;
  EXPECT_FALSE(ContactAnalyzer(two).analyze(synth::deformed(rest, synth::dimple(0.3, 0.9)), rest).in_contact);
}

TEST(ContactAnalyzer, TooFewMarkersIsReportedNotGuessed) {
  const MarkerField rest = synth::flatGrid(5, 5);
  MarkerField now = synth::deformed(rest, synth::dimple(1.0, 2.0));
  for (int i = 4; i < now.size(); ++i) now.valid[static_cast<size_t>(i)] = 0;
  const contact::ContactField cf = ContactAnalyzer().analyze(now, rest);
  EXPECT_EQ(cf.status, contact::ContactFieldStatus::too_few_markers);
  EXPECT_FALSE(cf.in_contact);
}

TEST(ContactAnalyzer, BadInputThrowsNamingTheProblem) {
  const MarkerField a = synth::flatGrid(5, 5), b = synth::flatGrid(5, 6);
  try {
    ContactAnalyzer().analyze(a, b);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("differs from the rest grid"), std::string::npos);
  }
  ContactAnalyzerOptions o;
  o.region_fraction = 1.5;
  EXPECT_THROW(ContactAnalyzer{o}, InputError);
  o = {};
  o.contact_threshold_mm = -1;
  EXPECT_THROW(ContactAnalyzer{o}, InputError);
}
