// The way back to a stick model (pose/anchored_fit.hpp fitConsensus and
// contact/stick_slip_classifier.hpp markSticking), on synthetic marker fields:
// a group moved by a known rigid motion over a window beside markers that
// slid by more than the trim threshold. Ground truth: the motion applied and
// which markers were made to slide.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "contact/stick_slip_classifier.hpp"
#include "core/rotation.hpp"
#include "pose/anchored_fit.hpp"

using namespace onetip;

namespace {

constexpr int kRows = 9, kCols = 9;
constexpr double kPitchMm = 1.2, kNoiseMm = 0.001, kTrimMm = 0.02;

MarkerField grid() {
  MarkerField f(kRows, kCols);
  for (int r = 0; r < kRows; ++r)
    for (int c = 0; c < kCols; ++c)
      f.set(r * kCols + c, {(c - 4) * kPitchMm, (r - 4) * kPitchMm, 0.02 * ((c - 4) * (c - 4) + (r - 4) * (r - 4))});
  return f;
}

struct Moved {
  MarkerField now;
  std::vector<int> sliders;
};

// Every marker follows `motion` (plus noise) but those with a slide drawn for
// them, which move by an extra random 0.05-0.3 mm in x-y.
Moved move(const MarkerField& before, const Eigen::Isometry3d& motion, double slide_probability, std::mt19937& rng) {
  std::normal_distribution<double> noise(0, kNoiseMm);
  std::uniform_real_distribution<double> u(0, 1), size(0.05, 0.3), angle(0, 2 * std::numbers::pi);
  Moved m{before, {}};
  for (int id = 0; id < before.size(); ++id) {
    Eigen::Vector3d p = motion * before.position[static_cast<size_t>(id)];
    p += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
    if (u(rng) < slide_probability) {
      const double a = angle(rng), s = size(rng);
      p += Eigen::Vector3d(s * std::cos(a), s * std::sin(a), 0);
      m.sliders.push_back(id);
    }
    m.now.set(id, p);
  }
  return m;
}

std::vector<int> allIds() {
  std::vector<int> ids(kRows * kCols);
  for (int i = 0; i < kRows * kCols; ++i) ids[static_cast<size_t>(i)] = i;
  return ids;
}

}  // namespace

TEST(RigidConsensus, KeepsTheMarkersThatMovedAsOneBodyAndTheirMotion) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> ang(-0.05, 0.05), tr(-0.5, 0.5);
  const MarkerField before = grid();
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Isometry3d motion =
        rigidFromTranslationYawPitchRoll({tr(rng), tr(rng), 0.2 * tr(rng)}, ang(rng), ang(rng), ang(rng));
    const Moved m = move(before, motion, 0.3, rng);
    std::vector<int> kept = allIds();
    const pose::RigidFit fit = pose::fitConsensus(kept, before, m.now, 4 * kNoiseMm, kTrimMm);
    ASSERT_TRUE(fit.ok);
    // exactly the markers that did not slide
    std::vector<int> expected;
    for (int id : allIds())
      if (std::find(m.sliders.begin(), m.sliders.end(), id) == m.sliders.end()) expected.push_back(id);
    EXPECT_EQ(kept, expected) << "trial " << trial;
    EXPECT_LT((fit.motion.translation() - motion.translation()).norm(), 5 * kNoiseMm) << "trial " << trial;
    EXPECT_LT(Eigen::AngleAxisd(fit.motion.linear().transpose() * motion.linear()).angle(), 5 * kNoiseMm / kPitchMm);
  }
}

TEST(RigidConsensus, ABodySmallerThanTheCountNeededIsNoConsensus) {
  // Trimming stops once the needed count remains: the body that stuck is found when it is that large,
  // and no consensus (members empty) when it is smaller.
  std::mt19937 rng(17);
  const MarkerField before = grid();
  const Moved m = move(before, rigidFromTranslationYawPitchRoll({0.2, -0.1, 0.05}, 0.01, 0.0, 0.02), 0.3, rng);
  const size_t body = static_cast<size_t>(kRows * kCols) - m.sliders.size();
  std::vector<int> kept = allIds();
  EXPECT_TRUE(pose::fitConsensus(kept, before, m.now, 4 * kNoiseMm, kTrimMm, body).ok);
  EXPECT_EQ(kept.size(), body);
  kept = allIds();
  EXPECT_FALSE(pose::fitConsensus(kept, before, m.now, 4 * kNoiseMm, kTrimMm, body + 1).ok);
  EXPECT_TRUE(kept.empty());
}

TEST(RigidConsensus, MarkersNotMeasuredInEitherFieldAreNotKept) {
  std::mt19937 rng(5);
  MarkerField before = grid();
  Moved m = move(before, Eigen::Isometry3d::Identity(), 0.0, rng);
  before.valid[10] = 0;
  m.now.valid[20] = 0;
  std::vector<int> kept = allIds();
  ASSERT_TRUE(pose::fitConsensus(kept, before, m.now, 4 * kNoiseMm, kTrimMm).ok);
  EXPECT_EQ(kept.size(), static_cast<size_t>(kRows * kCols - 2));
  EXPECT_EQ(std::count(kept.begin(), kept.end(), 10) + std::count(kept.begin(), kept.end(), 20), 0);
}

TEST(RigidConsensus, MarkSticking) {
  // The consensus sticks, every other anchored marker slips, all re-anchored under the pose; a marker
  // outside the contact stays outside.
  const MarkerField now = grid();
  contact::StickSlipClassifier classifier;
  classifier.reset(now.size());
  std::vector<int> members = allIds();
  members.pop_back();  // the last marker is outside
  classifier.retain(members, now);
  const Eigen::Isometry3d pose = rigidFromTranslationYawPitchRoll({0.3, -0.2, 0.1}, 0.02, 0.01, -0.01);
  classifier.anchorNew(members, now, Eigen::Isometry3d::Identity());
  classifier.markSticking({1, 2, 3}, now, pose);
  for (int id = 0; id < now.size(); ++id) {
    const contact::MarkerLabel expected = id == now.size() - 1 ? contact::MarkerLabel::outside
                                          : (id >= 1 && id <= 3) ? contact::MarkerLabel::stick
                                                                 : contact::MarkerLabel::slip;
    EXPECT_EQ(classifier.label(id), expected) << id;
    if (expected != contact::MarkerLabel::outside) {
      EXPECT_LT((pose * classifier.anchor(id) - now.position[static_cast<size_t>(id)]).norm(), 1e-12) << id;
    }
  }
}
