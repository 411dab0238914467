#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

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

namespace {

// Two fingers' dimples (synth::dimple, both `width` wide): `deep` mm at x = `x_deep`, `shallow` mm at x = `x_shallow`
// (y = `y_shallow`).
std::function<Eigen::Vector3d(const Eigen::Vector3d&)> twoDimples(double deep, double x_deep, double shallow,
                                                                  double x_shallow, double width,
                                                                  double y_shallow = 0) {
  return [=](const Eigen::Vector3d& p) {
    return Eigen::Vector3d(synth::dimple(deep, width, x_deep, 0)(p) +
                           synth::dimple(shallow, width, x_shallow, y_shallow)(p));
  };
}

// The region of a field whose rest centroid lies on the side of x = 0 that `side` (-1 or +1) names.
const contact::ContactRegion& regionOnSide(const contact::ContactField& cf, int side) {
  return (cf.regions[0].rest_centroid.x() < 0) == (side < 0) ? cf.regions[0] : cf.regions[1];
}

}  // namespace

TEST(ContactAnalyzer, TwoFingersGiveTwoRegions) {
  const MarkerField rest = synth::flatGrid(17, 17);
  const auto u = twoDimples(1.0, -5, 0.8, 5, 1.8, 1);
  const contact::ContactField cf = ContactAnalyzer().analyze(synth::deformed(rest, u), rest);
  ASSERT_EQ(cf.regions.size(), 2u);
  // Each finger is cut at 40 % of its own peak: the same share of each imprint, whatever its depth.
  const contact::ContactRegion &left = regionOnSide(cf, -1), &right = regionOnSide(cf, 1);
  EXPECT_LT(left.rest_centroid.x(), -3.5);
  EXPECT_GT(right.rest_centroid.x(), 3.5);
  EXPECT_NEAR(left.peak_normal_mm, 1.0, 0.02);
  EXPECT_NEAR(right.peak_normal_mm, 0.8, 0.02);
  EXPECT_NEAR(left.cut_mm, 0.4 * left.peak_normal_mm, 1e-12);
  EXPECT_NEAR(right.cut_mm, 0.4 * right.peak_normal_mm, 1e-12);
  for (int id : right.markers) EXPECT_GE(-u(rest.position[static_cast<size_t>(id)]).z(), 0.4 * right.peak_normal_mm);
}

TEST(ContactAnalyzer, AShallowFingerBesideADeepOneKeepsItsRegion) {
  // 1 mm and 0.3 mm deep, 10 mm apart: the shallow imprint lies below 40 % of the deep one's peak, where one
  // global cut left it no region at all; it is a touch of its own (beyond the 0.1 mm contact threshold).
  const MarkerField rest = synth::flatGrid(17, 17);
  const auto u = twoDimples(1.0, -5, 0.3, 5, 1.8);
  const contact::ContactField cf = ContactAnalyzer().analyze(synth::deformed(rest, u), rest);
  ASSERT_EQ(cf.regions.size(), 2u);
  const contact::ContactRegion& shallow = regionOnSide(cf, 1);
  EXPECT_GT(shallow.rest_centroid.x(), 3.5);
  EXPECT_NEAR(shallow.peak_normal_mm, 0.3, 0.01);
  // Independent answer: on the shallow finger's side, the markers at or above 40 % of its peak.
  for (int i = 0; i < rest.size(); ++i) {
    const Eigen::Vector3d& p = rest.position[static_cast<size_t>(i)];
    if (p.x() < 2) continue;
    const bool expected = -u(p).z() >= 0.4 * shallow.peak_normal_mm;
    EXPECT_EQ(std::find(shallow.markers.begin(), shallow.markers.end(), i) != shallow.markers.end(), expected) << i;
  }
}

TEST(ContactAnalyzer, TwoFingersWhoseImprintsJoinAreStillTwoRegions) {
  // 6 mm apart: the deformation between them stays above the 40 % cut, so the
  // markers above it form one connected area (checked below); the valley splits it.
  const MarkerField rest = synth::flatGrid(17, 17);
  const auto u = twoDimples(1.0, -3, 0.8, 3, 2.5);
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
