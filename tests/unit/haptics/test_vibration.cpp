// The vibration channel: 6-pole/6-zero fits from a 2 s swept sine through the
// simulated plant against the plant's true response (20-800 Hz), and
// configuration switches without clicks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>

#include "core/error.hpp"

#include "haptics/platform_kinematics.hpp"
#include "haptics/tf_identification.hpp"
#include "haptics/vibration_channel.hpp"
#include "haptics/vibration_plant.hpp"
#include "haptics/vibration_table.hpp"
#include "scratch_dir.hpp"

using namespace onetip::haptics;

namespace {

const std::vector<std::array<double, 3>> kConfigurations = {{30, 30, 30}, {120, 120, 120}, {195, 195, 195},
                                                            {160, 60, 90}, {90, 180, 140}};

double worstErrorDb(const TransferFunction& fit, const TransferFunction& truth) {
  double worst = 0.0;
  for (double f = 20.0; f <= 800.0; f *= 1.02) worst = std::max(worst, std::abs(fit.gainDb(f) - truth.gainDb(f)));
  return worst;
}

}  // namespace

TEST(VibrationIdentification, CleanSweepFitsWithin1dB) {
  const PlatformKinematics device;
  const auto u = sweptSine();
  ASSERT_EQ(u.size(), 4400u);
  for (const auto& m : kConfigurations) {
    const TransferFunction truth = vibrationPlant(device.forward(m));
    const auto fit = identifyTransferFunction(u, filterSignal(truth, u));
    EXPECT_TRUE(fit.tf.stable());
    EXPECT_LT(worstErrorDb(fit.tf, truth), 1.0) << m[0] << "," << m[1] << "," << m[2];
  }
}

TEST(VibrationIdentification, NoisySweepAt30dBFitsWithin2dB) {
  const PlatformKinematics device;
  const auto u = sweptSine();
  unsigned seed = 1;
  for (const auto& m : kConfigurations) {
    const TransferFunction truth = vibrationPlant(device.forward(m));
    const auto fit = identifyTransferFunction(u, withRecordingNoise(filterSignal(truth, u), 30.0, seed++));
    EXPECT_TRUE(fit.tf.stable());
    EXPECT_LT(worstErrorDb(fit.tf, truth), 2.0) << m[0] << "," << m[1] << "," << m[2];
  }
}

TEST(VibrationIdentification, ResonanceMovesWithTheConfiguration) {
  const PlatformKinematics device;
  auto peak = [](const TransferFunction& tf) {
    double best_f = 0, best = -1e9;
    for (double f = 50; f < 700; f += 1)
      if (tf.gainDb(f) > best) best = tf.gainDb(f), best_f = f;
    return best_f;
  };
  EXPECT_LT(peak(vibrationPlant(device.forward({30, 30, 30}))), peak(vibrationPlant(device.forward({195, 195, 195}))) - 100);
}

TEST(VibrationChannel, SwitchingConfigurationsMakesNoClick) {
  const PlatformKinematics device;
  const TransferFunction soft = vibrationPlant(device.forward({60, 60, 60}));
  const TransferFunction hard = vibrationPlant(device.forward({195, 160, 120}));
  // A sensed AC signal: a texture-like mix of tones and noise.
  std::mt19937 rng(3);
  std::normal_distribution<double> n01;
  std::vector<double> x(6000);
  for (size_t k = 0; k < x.size(); ++k) {
    const double t = static_cast<double>(k) / kVibrationRateHz;
    x[k] = std::sin(2 * M_PI * 90 * t) + 0.6 * std::sin(2 * M_PI * 230 * t + 1) + 0.05 * n01(rng);
  }
  auto largestStep = [](const std::vector<double>& y, size_t from, size_t to) {
    double s = 0;
    for (size_t k = std::max<size_t>(from, 1); k < to; ++k) s = std::max(s, std::abs(y[k] - y[k - 1]));
    return s;
  };
  const auto y_soft = filterSignal(soft, x), y_hard = filterSignal(hard, x);
  const double own = std::max(largestStep(y_soft, 500, x.size()), largestStep(y_hard, 500, x.size()));

  VibrationChannel channel(soft);
  std::vector<double> y(x.size());
  const std::vector<size_t> switches = {1000, 1500, 1510, 3000, 3001, 4500};
  for (size_t k = 0; k < x.size(); ++k) {
    for (size_t i = 0; i < switches.size(); ++i)
      if (k == switches[i]) channel.select(i % 2 == 0 ? hard : soft);
    y[k] = channel.process(x[k]);
  }
  for (size_t s : switches) EXPECT_LE(largestStep(y, s, s + 60), own) << "switch at " << s;
  // Away from switches the channel is exactly the selected filter.
  EXPECT_NEAR(y[900], y_soft[900], 1e-12);
  // Control: a naive switch (new filter from rest, no crossfade) at an output
  // peak clicks by more than the signal's own largest step.
  size_t peak = 1000;
  for (size_t k = 1000; k < 1100; ++k)
    if (std::abs(y_soft[k]) > std::abs(y_soft[peak])) peak = k;
  IirFilter naive(soft);
  std::vector<double> y_naive(x.size());
  for (size_t k = 0; k < x.size(); ++k) {
    if (k == peak) naive = IirFilter(hard);
    y_naive[k] = naive.process(x[k]);
  }
  EXPECT_GT(largestStep(y_naive, peak, peak + 60), own);
}

// Algorithm 1's table: every entry fitted within 1 dB of the plant at its own
// configuration (clean records), lookups go to the entry nearest in every
// motor (checked against a scan of all entries), and a saved table loads back
// exactly; a damaged file is refused.
TEST(VibrationTable, EntriesFitTheirPlantAndLookupPicksTheNearestConfiguration) {
  const PlatformKinematics device;
  VibrationTableOptions o;
  o.step_deg = 55.0;  // 30, 85, 140 per motor: 27 entries
  o.identification.max_iterations = 5;
  const VibrationTable table = VibrationTable::identify(simulatedSweepRecorder(device), o);
  ASSERT_EQ(table.size(), 27u);
  for (size_t i = 0; i < table.size(); ++i)
    EXPECT_LT(worstErrorDb(table.entry(i), vibrationPlant(device.forward(table.configuration(i)))), 1.0) << i;

  std::mt19937 rng(5);
  std::uniform_real_distribution<double> angle(0.0, 220.0);  // also outside the servo range
  for (int trial = 0; trial < 200; ++trial) {
    const std::array<double, 3> m = {angle(rng), angle(rng), angle(rng)};
    size_t nearest = 0;
    double best = 1e300;
    for (size_t i = 0; i < table.size(); ++i) {
      const auto c = table.configuration(i);
      double gap_sq = 0.0;  // squared distance to the entry, angles clamped to the grid
      for (size_t k = 0; k < 3; ++k) gap_sq += std::pow(std::clamp(m[k], 30.0, 140.0) - c[k], 2);
      if (gap_sq < best) best = gap_sq, nearest = i;
    }
    EXPECT_EQ(table.index(m), nearest) << m[0] << "," << m[1] << "," << m[2];
    EXPECT_EQ(&table.lookup(m), &table.entry(nearest));
  }

  const onetip::test_support::ScratchDir scratch("onetip-vibration");
  const std::string path = scratch.file("vibration_table.csv");
  table.save(path);
  const VibrationTable loaded = VibrationTable::load(path);
  ASSERT_EQ(loaded.size(), table.size());
  for (size_t i = 0; i < table.size(); ++i) {
    EXPECT_EQ(loaded.entry(i).a, table.entry(i).a);
    EXPECT_EQ(loaded.entry(i).b, table.entry(i).b);
  }
  {
    std::ifstream in(path);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(path, std::ios::trunc) << text.substr(0, text.size() / 2);  // rows cut off
  }
  EXPECT_THROW(VibrationTable::load(path), onetip::InputError);
}
