// Which region markers the finger can be touching (pose/touching_markers.hpp),
// on synthetic normal-deformation fields over a 15 x 15 lattice at 1.2 mm:
// a spherical cap (radius 8 mm) 0.3 mm deep at the bottom of a 2 mm dip that
// relaxes convexly to rest around it (a soft foundation: the contact stage's
// 40 % region then holds about as many markers around the touch as under
// it), a flat plate, noise, and missing neighbours. Ground truth: which
// nodes lie under the cap.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "pose/touching_markers.hpp"

using namespace onetip;

namespace {

constexpr int kN = 15;
constexpr double kPitch = 1.2, kRadius = 8.0, kDepth = 0.3, kDip = 2.0;

struct Field {
  contact::ContactField field;
  std::vector<int> members;  // the contact stage's region: n at least 40 % of its peak
  std::vector<bool> under;   // the node lies under the cap
};

// n(r): the cap D + d - r^2 / 2R inside its edge a = sqrt(2 R d), outside
// D a / r, convex (its Laplacian D a / r^3 > 0): pressure-free skin relaxing
// to rest.
Field sphereField(double noise_mm, unsigned seed) {
  Field f;
  const int n = kN * kN;
  f.field.displacement.assign(n, Eigen::Vector3d::Zero());
  f.field.valid.assign(n, 1);
  f.under.assign(n, false);
  const double a = std::sqrt(2 * kRadius * kDepth), edge = kDip;  // n at the cap's edge
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0, noise_mm);
  for (int id = 0; id < n; ++id) {
    const double x = (id % kN - kN / 2) * kPitch, y = (id / kN - kN / 2) * kPitch, r = std::hypot(x, y);
    const bool inside = r < a;
    const double nd = inside ? edge + (a * a - r * r) / (2 * kRadius) : edge * a / r;
    f.field.displacement[static_cast<size_t>(id)].z() = -(nd + noise(rng));
    f.under[static_cast<size_t>(id)] = inside;
    if (nd >= 0.4 * (kDip + kDepth)) f.members.push_back(id);
  }
  return f;
}

// A node outside the cap with a neighbour under it.
bool besideCap(const Field& f, int id) {
  const int r = id / kN, c = id % kN;
  if (f.under[static_cast<size_t>(id)]) return false;
  for (const auto& [dr, dc] : {std::pair{0, 1}, {0, -1}, {1, 0}, {-1, 0}})
    if (f.under[static_cast<size_t>((r + dr) * kN + c + dc)]) return true;
  return false;
}

TEST(TouchingMarkers, UnderASphereTheCapIsKeptAndTheRelaxingSkinAroundItIsNot) {
  // A marker of the skin beside the cap's edge has a neighbour under the cap,
  // and the deformation bends down into the dimple across it (the edge's
  // kink): the test cannot tell it from the cap. Every marker under the cap
  // is kept, every marker further out is not.
  const Field f = sphereField(0.0, 1);
  const auto touching = pose::touchingMarkers(f.field, f.members, kN, kN, 0.0006, 0.5);
  int under = 0, kept_under = 0, beyond = 0, kept_beyond = 0;
  for (int id : f.members) {
    if (f.under[static_cast<size_t>(id)]) ++under, kept_under += touching[static_cast<size_t>(id)];
    else if (!besideCap(f, id)) ++beyond, kept_beyond += touching[static_cast<size_t>(id)];
  }
  std::printf("under the cap %d (kept %d), beyond the markers beside it %d (kept %d)\n", under, kept_under, beyond,
              kept_beyond);
  ASSERT_GE(under, 9);
  ASSERT_GE(beyond, 4);
  EXPECT_EQ(kept_under, under);
  EXPECT_EQ(kept_beyond, 0);
}

TEST(TouchingMarkers, NoiseOfAFlatFieldIsNotReadAsCurvature) {
  // A flat plate pressed 1 mm: the Laplacian is noise alone; at 3 sigma of
  // its spread almost every marker is kept.
  Field f = sphereField(0.0, 2);
  std::mt19937 rng(3);
  const double sigma = 0.002;
  std::normal_distribution<double> noise(0, sigma);
  std::vector<int> all;
  for (int id = 0; id < kN * kN; ++id) {
    f.field.displacement[static_cast<size_t>(id)].z() = -(1.0 + noise(rng));
    all.push_back(id);
  }
  const auto touching = pose::touchingMarkers(f.field, all, kN, kN, sigma, 0.5);
  int kept = 0;
  for (int id : all) kept += touching[static_cast<size_t>(id)];
  EXPECT_GE(kept, kN * kN - 3);
  // Judged at a tenth of the real noise, the same field loses many markers:
  // the bound is what makes the test hold.
  const auto strict = pose::touchingMarkers(f.field, all, kN, kN, 0.1 * sigma, 0.5);
  int kept_strict = 0;
  for (int id : all) kept_strict += strict[static_cast<size_t>(id)];
  EXPECT_LT(kept_strict, kN * kN - 30);
}

TEST(TouchingMarkers, AMarkerWithANeighbourMissingIsKeptNonMembersAreNotAndNoLatticeKeepsAll) {
  // The convex test alone (no core: a core would drop the marker below for being shallower than the cap).
  Field f = sphereField(0.0, 4);
  // A marker of the relaxing skin, judged out with all its neighbours.
  int skin = -1;
  const auto before = pose::touchingMarkers(f.field, f.members, kN, kN, 0.0006, 0.0);
  for (int id : f.members)
    if (!f.under[static_cast<size_t>(id)] && !before[static_cast<size_t>(id)] && id % kN > 0) skin = id;
  ASSERT_GE(skin, 0);
  f.field.valid[static_cast<size_t>(skin - 1)] = 0;
  const auto after = pose::touchingMarkers(f.field, f.members, kN, kN, 0.0006, 0.0);
  EXPECT_TRUE(after[static_cast<size_t>(skin)]);
  const auto none = pose::touchingMarkers(f.field, {}, kN, kN, 0.0006, 0.5);
  for (auto t : none) EXPECT_FALSE(t);
  // No lattice to judge by (a field without its rows and columns): every member kept.
  const auto unjudged = pose::touchingMarkers(f.field, f.members, 0, 0, 0.0006, 0.5);
  for (int id : f.members) EXPECT_TRUE(unjudged[static_cast<size_t>(id)]);
}

// A cap (radius R, depth d, its edge at n = E) at the bottom of a dent that
// decays as a Pasternak foundation's, n = E K0(r / l) / K0(a / l) outside the
// cap's edge a = sqrt(2 R d); members: n at least 40 % of its peak.
Field foundationField(double cap_radius, double cap_depth, double edge, double length, double noise_mm,
                      unsigned seed) {
  Field f;
  const int n = kN * kN;
  f.field.displacement.assign(n, Eigen::Vector3d::Zero());
  f.field.valid.assign(n, 1);
  f.under.assign(n, false);
  const double a = std::sqrt(2 * cap_radius * cap_depth);
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0, noise_mm);
  for (int id = 0; id < n; ++id) {
    const double x = (id % kN - kN / 2) * kPitch, y = (id / kN - kN / 2) * kPitch, r = std::hypot(x, y);
    const bool inside = r < a;
    const double nd = inside ? edge + (a * a - r * r) / (2 * cap_radius)
                             : edge * std::cyl_bessel_k(0.0, r / length) / std::cyl_bessel_k(0.0, a / length);
    f.field.displacement[static_cast<size_t>(id)].z() = -(nd + noise(rng));
    f.under[static_cast<size_t>(id)] = inside;
    if (nd >= 0.4 * (edge + cap_depth)) f.members.push_back(id);
  }
  return f;
}

// Early in a press into a foundation: the same cap at the bottom of a dent
// that decays as a Pasternak foundation's, n = E K0(r / l) / K0(a / l) with a
// long l = 15 mm, so the skin beside the touch is only faintly convex
// (L = n h^2 / l^2, under the convex cut) and fills most of the 40 % region.
TEST(TouchingMarkers, TheCapsConcaveCoreLeavesOutFaintlyConvexSkinBesideTheTouch) {
  constexpr double kSigma = 0.0006;
  const Field f = foundationField(kRadius, kDepth, 1.0, 15.0, kSigma, 5);
  // Skin beyond the markers beside the cap's edge (those, with a neighbour under the cap, are kept by
  // either test: the deformation bends down into the dimple across them).
  int under = 0, beyond = 0;
  for (int id : f.members) {
    under += f.under[static_cast<size_t>(id)];
    beyond += !f.under[static_cast<size_t>(id)] && !besideCap(f, id);
  }
  const auto count = [&](const std::vector<std::uint8_t>& t, bool under_cap) {
    int k = 0;
    for (int id : f.members)
      k += t[static_cast<size_t>(id)] && (under_cap ? f.under[static_cast<size_t>(id)]
                                                    : !f.under[static_cast<size_t>(id)] && !besideCap(f, id));
    return k;
  };
  const auto convex_only = pose::touchingMarkers(f.field, f.members, kN, kN, kSigma, 0.0);
  const auto with_core = pose::touchingMarkers(f.field, f.members, kN, kN, kSigma, 0.5);
  std::printf("members %zu: under the cap %d, beyond the skin beside it %d; kept by the convex test %d + %d, "
              "with the core %d + %d\n",
              f.members.size(), under, beyond, count(convex_only, true), count(convex_only, false),
              count(with_core, true), count(with_core, false));
  ASSERT_GE(beyond, 5 * under);                   // the faintly convex skin is most of the region
  EXPECT_GE(4 * count(convex_only, false), 3 * beyond);  // the convex test keeps most of it
  EXPECT_EQ(count(with_core, false), 0);            // the core's depth leaves it out
  EXPECT_EQ(count(with_core, true), under);         // and keeps the cap
  // A core that spans an area: the cap of a small contact is the same set.
  const auto cap = pose::capMarkers(f.field, f.members, kN, kN, kSigma);
  for (int id : f.members) EXPECT_EQ(cap[static_cast<size_t>(id)], with_core[static_cast<size_t>(id)]) << id;
}

// A coarse pattern as a small finger's press begins: the cap (radius 6 mm,
// 0.1 mm deep) holds the single marker at its centre, at the bottom of a
// dip that decays as a foundation's of l = 4.5 mm (campaign seed 119's
// regime), and the skin beside the touch fills the region. The concave core
// is that one marker, too small to span an area (touchingMarkers would not
// use it); the cap is the touch.
TEST(TouchingMarkers, ASmallContactsCapIsTheTouchNotTheSkinBesideIt) {
  constexpr double kSigma = 0.0006;
  Field f = foundationField(6.0, 0.1, 0.1, 4.5, kSigma, 7);  // cap edge a = 1.10 mm: only the centre under it
  int under = 0;
  for (int id : f.members) under += f.under[static_cast<size_t>(id)];
  ASSERT_EQ(under, 1);
  ASSERT_GE(f.members.size(), 5u);
  const auto cap = pose::capMarkers(f.field, f.members, kN, kN, kSigma);
  int cap_kept = 0, skin_in_cap = 0;
  for (int id : f.members) {
    const size_t i = static_cast<size_t>(id);
    cap_kept += f.under[i] && cap[i];
    skin_in_cap += !f.under[i] && cap[i];
  }
  std::printf("members %zu, under the cap %d; the cap keeps %d of it and %d skin\n", f.members.size(), under,
              cap_kept, skin_in_cap);
  EXPECT_EQ(cap_kept, 1);
  EXPECT_EQ(skin_in_cap, 0);

  // No concave core (a plate pressed flat, with noise): no cap, nothing is found directly.
  std::mt19937 rng(8);
  std::normal_distribution<double> noise(0, kSigma);
  for (auto& u : f.field.displacement) u.z() = -(0.5 + noise(rng));
  const auto flat = pose::capMarkers(f.field, f.members, kN, kN, kSigma);
  for (auto c : flat) EXPECT_FALSE(c);
  // No lattice to judge by: no cap either.
  for (auto c : pose::capMarkers(f.field, f.members, 0, 0, kSigma)) EXPECT_FALSE(c);
}

}  // namespace

TEST(TouchingMarkers, DetachedMarkersUnderTheFingerStickAgainOnlyWhenNoneOfThemSticks) {
  // Over the synthetic sphere field: the markers the test keeps as touching are labelled detached (the
  // estimate lagged a press), the skin around them stick. They are returned, to stick again; not when one
  // of them still sticks, not when fewer than the minimum are detached, not when the test kept every member
  // (it found no edge), and a marker not measured now, or a frame ago, is never returned.
  const Field f = sphereField(0.0, 1);
  const auto touching = pose::touchingMarkers(f.field, f.members, kN, kN, 0.0006, 0.5);
  std::vector<contact::MarkerLabel> labels(touching.size(), contact::MarkerLabel::outside);
  std::vector<int> under;
  for (int id : f.members) {
    const bool touched = touching[static_cast<size_t>(id)] != 0;
    labels[static_cast<size_t>(id)] = touched ? contact::MarkerLabel::detached : contact::MarkerLabel::stick;
    if (touched) under.push_back(id);
  }
  ASSERT_GE(under.size(), 9u);
  MarkerField now(kN, kN);
  for (int id : f.members) now.valid[static_cast<size_t>(id)] = 1;
  EXPECT_EQ(pose::detachedUnderTheFinger(f.members, touching, labels, now, now, 4), under);

  now.valid[static_cast<size_t>(under.front())] = 0;  // not measured this frame: left as it is
  EXPECT_EQ(pose::detachedUnderTheFinger(f.members, touching, labels, now, now, 4),
            std::vector<int>(under.begin() + 1, under.end()));
  now.valid[static_cast<size_t>(under.front())] = 1;
  MarkerField before = now;
  before.valid[static_cast<size_t>(under.back())] = 0;  // not measured a frame ago: nowhere to anchor it
  EXPECT_EQ(pose::detachedUnderTheFinger(f.members, touching, labels, before, now, 4),
            std::vector<int>(under.begin(), under.end() - 1));

  EXPECT_TRUE(pose::detachedUnderTheFinger(f.members, touching, labels, now, now, static_cast<int>(under.size()) + 1).empty());
  auto one_sticks = labels;
  one_sticks[static_cast<size_t>(under.back())] = contact::MarkerLabel::stick;
  EXPECT_TRUE(pose::detachedUnderTheFinger(f.members, touching, one_sticks, now, now, 4).empty());
  const std::vector<std::uint8_t> all_touching(touching.size(), 1);
  EXPECT_TRUE(pose::detachedUnderTheFinger(f.members, all_touching, labels, now, now, 4).empty());
}
