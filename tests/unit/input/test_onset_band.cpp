// A field that sinks through the contact threshold starts no contact from
// noise (input/onset_band.hpp), on synthetic fields: a dimple of N markers
// whose noiseless depth is known frame by frame, with Gaussian noise of a
// known sd per axis. The contact rule is the analyser's (max |u_i| above the
// threshold) with the onset gated by the band, as the tracker does.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "input/onset_band.hpp"

using namespace onetip::input;

namespace {

constexpr double kThresholdMm = 0.1;  // the paper's contact threshold
constexpr double kNoiseMm = 0.001;    // per axis
constexpr int kSide = 17;             // 289 markers, pitch 1 mm

// The largest measured modulus of a Gaussian dimple of depth `peak_mm` (radius 2 mm) on the grid, each marker's
// displacement along -z with independent noise per axis.
double measuredMaximum(double peak_mm, std::mt19937& rng) {
  std::normal_distribution<double> n(0, kNoiseMm);
  double m = 0;
  for (int r = 0; r < kSide; ++r)
    for (int c = 0; c < kSide; ++c) {
      const double x = c - kSide / 2, y = r - kSide / 2;
      const double u = peak_mm * std::exp(-(x * x + y * y) / 8);
      m = std::max(m, std::sqrt(std::pow(n(rng), 2) + std::pow(n(rng), 2) + std::pow(-u + n(rng), 2)));
    }
  return m;
}

// Plays noiseless depths through the contact rule with the band; returns the frames a contact began in.
std::vector<int> onsets(const std::vector<double>& depth_mm, OnsetBand& band, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<int> out;
  bool contact = false;
  for (size_t k = 0; k < depth_mm.size(); ++k) {
    const double m = measuredMaximum(depth_mm[k], rng);
    const bool may_begin = band.mayBegin(m, kSide * kSide, kNoiseMm, kThresholdMm);
    const bool in = m > kThresholdMm && (contact || may_begin);
    if (in && !contact) out.push_back(static_cast<int>(k));
    contact = in;
  }
  return out;
}

// A held press that lifts off, leaving a delayed part that decays by `alpha` per frame from `left_mm` (a
// creeping gel after a lift-off): the first frame is in contact, nothing touches afterwards.
std::vector<double> decayingGel(double left_mm, double alpha, int frames) {
  std::vector<double> d = {0.5};
  for (int k = 0; k < frames; ++k) d.push_back(left_mm * std::pow(alpha, k));
  return d;
}

}  // namespace

TEST(OnsetBand, TheBarIsTheLargestNoiseVectorOfTheMarkers) {
  // The half-width is the noise sd times the bound the largest of N three-component noise vectors passes with
  // the false-alarm probability: drawn, it is passed about that often.
  OnsetBandOptions o;
  o.false_alarm = 0.05;
  const OnsetBand band(o);
  const double b = band.halfWidth(kSide * kSide, kNoiseMm);
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0, kNoiseMm);
  int beyond = 0;
  const int trials = 4000;
  for (int t = 0; t < trials; ++t) {
    double worst = 0;
    for (int i = 0; i < kSide * kSide; ++i) worst = std::max(worst, std::hypot(n(rng), n(rng), n(rng)));
    beyond += worst > b ? 1 : 0;
  }
  EXPECT_NEAR(beyond / static_cast<double>(trials), o.false_alarm, 0.015);
}

TEST(OnsetBand, AGelDecayingThroughTheThresholdStartsNoContact) {
  // Slow decays (0.1-0.5 % per frame, a slow gel at a high frame rate) spend tens of frames within the noise of
  // the threshold. Without the band the noise starts contacts there; with it, none over 40 runs.
  int with_band = 0, without_band = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    const double alpha = 1 - 0.001 * (1 + seed % 5);
    const std::vector<double> depth = decayingGel(0.12, alpha, 600);
    OnsetBand band;
    OnsetBandOptions off;
    off.enabled = false;
    OnsetBand none(off);
    // The first frame (the held press) begins the one true contact.
    with_band += static_cast<int>(onsets(depth, band, seed).size()) - 1;
    without_band += static_cast<int>(onsets(depth, none, seed).size()) - 1;
  }
  EXPECT_EQ(with_band, 0);
  EXPECT_GT(without_band, 0);  // the case is real: noise alone lifts such a field back over the threshold
}

TEST(OnsetBand, AFingerPressingAgainBeginsOnceItRisesBeyondTheNoise) {
  // The gel sinks through the threshold and lingers just below it, within the bar; a finger then presses at
  // 0.002 mm per frame. The contact begins at the latest where the noiseless field is above the threshold by twice
  // the bar (noise lowers the measured maximum by less than one bar), and not before the noiseless field passes
  // the threshold (noise lifts it by less than one bar).
  for (unsigned seed = 1; seed <= 20; ++seed) {
    std::vector<double> depth = {0.5};
    for (int k = 0; k < 40; ++k) depth.push_back(0.11 * std::pow(0.997, k));
    const double low = depth.back();
    for (int k = 1; k <= 60; ++k) depth.push_back(low + 0.002 * k);
    OnsetBand band;
    const double b = band.halfWidth(kSide * kSide, kNoiseMm);
    const std::vector<int> begun = onsets(depth, band, seed);
    ASSERT_EQ(begun.size(), 2u) << "seed " << seed;
    int latest = 0, earliest = 0;
    for (int k = 41; k < static_cast<int>(depth.size()); ++k) {
      if (!earliest && depth[static_cast<size_t>(k)] > kThresholdMm) earliest = k;
      if (!latest && depth[static_cast<size_t>(k)] > kThresholdMm + 2 * b) latest = k;
    }
    EXPECT_GE(begun[1], earliest) << "seed " << seed;
    EXPECT_LE(begun[1], latest) << "seed " << seed;
  }
}

TEST(OnsetBand, APressFromRestBeginsAtTheThresholdAsBefore) {
  // Nothing sank through the threshold: the band does not act, the first contact begins where the measured
  // maximum first passes the threshold, as the contact rule alone has it.
  for (unsigned seed = 1; seed <= 20; ++seed) {
    std::vector<double> depth;
    for (int k = 0; k < 60; ++k) depth.push_back(0.004 * k);
    OnsetBand band;
    OnsetBandOptions off;
    off.enabled = false;
    OnsetBand none(off);
    const std::vector<int> gated = onsets(depth, band, seed), plain = onsets(depth, none, seed);
    ASSERT_FALSE(plain.empty());
    ASSERT_FALSE(gated.empty());
    EXPECT_EQ(gated.front(), plain.front()) << "seed " << seed;
  }
}

TEST(OnsetBand, OptionsAreChecked) {
  OnsetBandOptions o;
  o.false_alarm = 0.5;
  EXPECT_ANY_THROW(OnsetBand{o});
}
