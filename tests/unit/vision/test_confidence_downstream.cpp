// Per-marker confidence used downstream (issue 16): the contact stage treats a
// marker graded below ContactAnalyzerOptions::min_confidence as not measured
// for the frame, and the pose stage (through contact::trustedMarkers) does not
// follow it.
//  * Contact: a flat 9x9 field with a 0.5 mm Gaussian press; one marker far
//    from it pushed 1 mm into the pad. Graded 1 it is the deepest marker and
//    sets the region cut; graded 0.05 it is not measured: the cut and the
//    region are the press's alone.
//  * Pose: the simulator's slide_x marker fields (sim_replay.hpp); in every
//    contact frame a third of the in-contact markers drift along +y by
//    0.02 mm per frame since onset (a coherent wrong motion, as a tracker
//    that followed wrong corners would report). Graded 0.05 (below the
//    default 0.2) the output is frame by frame that of the same run with
//    those markers not measured at all; graded 1 the estimated dy follows
//    the drift (its error against the simulator's truth more than 3x larger).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "contact/contact_analyzer.hpp"
#include "sim_replay.hpp"

using namespace onetip;

namespace {

MarkerField pressedGrid(MarkerField* rest_out) {
  MarkerField rest(9, 9), now(9, 9);
  for (int r = 0; r < 9; ++r)
    for (int c = 0; c < 9; ++c) {
      const Eigen::Vector3d p(1.2 * (c - 4), 1.2 * (r - 4), 0.0);
      rest.set(r * 9 + c, p);
      const double dip = 0.5 * std::exp(-(p.x() * p.x() + p.y() * p.y()) / (2 * 1.5 * 1.5));
      now.set(r * 9 + c, p - Eigen::Vector3d(0, 0, dip));
    }
  *rest_out = rest;
  return now;
}

}  // namespace

TEST(ConfidenceDownstream, ContactTreatsALowConfidenceMarkerAsNotMeasured) {
  MarkerField rest;
  MarkerField now = pressedGrid(&rest);
  const int far = 0;  // corner marker, 6.8 mm from the press
  now.position[far].z() -= 1.0;
  const contact::ContactAnalyzer analyzer;
  const contact::ContactField trusted_all = analyzer.analyze(now, rest);
  EXPECT_NEAR(trusted_all.max_normal_mm, 1.0, 1e-3);  // the displaced marker sets the cut
  EXPECT_EQ(trusted_all.low_confidence, 0);

  now.confidence[far] = 0.05f;
  const contact::ContactField field = analyzer.analyze(now, rest);
  EXPECT_EQ(field.low_confidence, 1);
  EXPECT_FALSE(field.valid[far]);
  EXPECT_FLOAT_EQ(field.confidence[far], 0.05f);
  EXPECT_NEAR(field.max_normal_mm, 0.5, 1e-9);  // the press alone
  ASSERT_TRUE(field.in_contact);
  EXPECT_FALSE(field.inRegion(far));
  EXPECT_TRUE(field.inRegion(4 * 9 + 4));
  const MarkerField seen = contact::trustedMarkers(now, field);
  EXPECT_EQ(seen.validCount(), now.validCount() - 1);
  EXPECT_FALSE(seen.valid[far]);

  contact::ContactAnalyzerOptions every;
  every.min_confidence = 0;  // grading off: the marker is used again
  EXPECT_NEAR(contact::ContactAnalyzer(every).analyze(now, rest).max_normal_mm, 1.0, 1e-3);
}

namespace {

// A third of the in-contact markers (diagonal stripes (row + col) % 3 == 0)
// drift along +y by 0.02 mm per frame since onset and are graded
// `confidence`; with `drop`, they are not measured at all instead.
poseval::Recording drifted(const poseval::Recording& clean, float confidence, bool drop = false) {
  poseval::Recording out = clean;
  int onset = -1;
  for (size_t k = 0; k < out.frames.size(); ++k) {
    const sim::GroundTruthFrame& truth = out.truth[k];
    if (!truth.in_contact) continue;
    if (onset < 0) onset = static_cast<int>(k);
    const double drift = 0.02 * (static_cast<int>(k) - onset);
    MarkerField& f = out.frames[k];
    for (int id = 0; id < f.size(); ++id) {
      const size_t i = static_cast<size_t>(id);
      if (!truth.contact[i] || !f.valid[i] || (id / f.cols + id % f.cols) % 3 != 0) continue;
      f.position[i].y() += drift;
      f.confidence[i] = confidence;
      if (drop) f.valid[i] = 0;
    }
  }
  return out;
}

// RMS of (estimated - true) dy over the frames both call contact.
double dyRmse(const std::vector<poseval::ReplayFrame>& frames) {
  double sum = 0;
  int n = 0;
  for (const poseval::ReplayFrame& f : frames) {
    if (!f.gt_contact || !f.contact) continue;
    sum += (f.composed.dy - f.gt.dy) * (f.composed.dy - f.gt.dy);
    ++n;
  }
  return n > 0 ? std::sqrt(sum / n) : INFINITY;
}

}  // namespace

TEST(ConfidenceDownstream, PoseDoesNotFollowDisplacedLowConfidenceMarkers) {
  const poseval::Recording clean = poseval::record(poseval::sampleScenario("slide_x"));
  const auto followed = poseval::track(drifted(clean, 1.0f));
  const auto graded_low = poseval::track(drifted(clean, 0.05f));
  const auto dropped = poseval::track(drifted(clean, 1.0f, true));
  std::printf("slide_x dy RMSE: clean %.4f mm; a third of the contact drifting, graded 1 %.4f mm, graded 0.05 %.4f mm, "
              "not measured %.4f mm\n",
              dyRmse(poseval::track(clean)), dyRmse(followed), dyRmse(graded_low), dyRmse(dropped));
  // Graded low is exactly "not measured": the same output frame by frame.
  ASSERT_EQ(graded_low.size(), dropped.size());
  for (size_t k = 0; k < dropped.size(); ++k) {
    EXPECT_EQ(graded_low[k].contact, dropped[k].contact) << "frame " << k;
    const auto a = graded_low[k].composed.asArray(), b = dropped[k].composed.asArray();
    for (size_t j = 0; j < a.size(); ++j) EXPECT_NEAR(a[j], b[j], 1e-12) << "frame " << k << " component " << j;
  }
  // Graded 1 the pose follows the drift (measured 0.22 against 0.05 mm).
  EXPECT_GT(dyRmse(followed), 3 * dyRmse(graded_low));
}
