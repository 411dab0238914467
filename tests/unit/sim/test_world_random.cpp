// The random generator's world effects (sim/random_scenario.hpp): off unless
// asked, and then drawn from their own stream (the scenario is otherwise the
// same draw for draw, so the existing campaign is unchanged), each on in
// about half the runs within its documented range, every run valid and
// playable.
#include <gtest/gtest.h>

#include "sim/random_scenario.hpp"
#include "sim/simulator.hpp"

using namespace onetip;
using namespace onetip::sim;

TEST(RandomWorld, FlagOffDrawsNoEffectAndFlagOnLeavesTheRestOfTheScenarioAlone) {
  for (unsigned seed = 1; seed <= 50; ++seed) {
    const RandomScenario off = randomScenario(seed), on = randomScenario(seed, true);
    EXPECT_FALSE(off.scenario.world.any()) << "seed " << seed;
    EXPECT_EQ(off.conditions.fps, on.conditions.fps);
    EXPECT_EQ(off.conditions.friction, on.conditions.friction);
    EXPECT_EQ(off.conditions.markers, on.conditions.markers);
    EXPECT_EQ(off.scenario.image.noise_sigma, on.scenario.image.noise_sigma);
    ASSERT_EQ(off.scenario.indenters.size(), on.scenario.indenters.size());
    for (size_t i = 0; i < off.scenario.indenters.size(); ++i) {
      const auto &a = off.scenario.indenters[i].keyframes, &b = on.scenario.indenters[i].keyframes;
      ASSERT_EQ(a.size(), b.size());
      for (size_t k = 0; k < a.size(); ++k) {
        EXPECT_EQ(a[k].t, b[k].t);
        EXPECT_EQ(a[k].x, b[k].x);
        EXPECT_EQ(a[k].depth, b[k].depth);
        EXPECT_EQ(a[k].roll, b[k].roll);
      }
    }
  }
}

TEST(RandomWorld, EachEffectIsOnInAboutHalfTheRunsWithinItsRange) {
  int ve = 0, shift = 0, damage = 0, light = 0, drift = 0;
  constexpr int kRuns = 200;
  for (unsigned seed = 1; seed <= kRuns; ++seed) {
    const WorldEffects w = randomScenario(seed, true).scenario.world;
    EXPECT_NO_THROW(w.viscoelastic.validate());
    EXPECT_NO_THROW(w.drift.validate());
    EXPECT_NO_THROW(w.camera_shift.validate());
    EXPECT_NO_THROW(w.damage.validate());
    EXPECT_NO_THROW(w.light.validate());
    if (w.viscoelastic.enabled()) {
      ++ve;
      EXPECT_GE(w.viscoelastic.relaxation, 0.1);
      EXPECT_LE(w.viscoelastic.relaxation, 0.4);
      EXPECT_GE(w.viscoelastic.time_s, 0.05);
      EXPECT_LE(w.viscoelastic.time_s, 5);
    }
    if (w.camera_shift.enabled()) {
      ++shift;
      EXPECT_GE(w.camera_shift.shift_px.norm(), 1 - 1e-9);
      EXPECT_LE(w.camera_shift.shift_px.norm(), 5 + 1e-9);
    }
    if (w.damage.enabled()) {
      ++damage;
      EXPECT_LE(w.damage.fraction, 0.05);
    }
    if (w.light.enabled()) {
      ++light;
      EXPECT_LE(w.light.flicker, 0.1);
      EXPECT_LE(std::abs(w.light.exposure_step), 0.3);
    }
    if (w.drift.enabled()) {
      ++drift;
      EXPECT_LE(std::abs(w.drift.expansion), 0.003);
    }
  }
  for (int n : {ve, shift, damage, light, drift}) {
    EXPECT_GT(n, kRuns * 0.35);
    EXPECT_LT(n, kRuns * 0.65);
  }
}

TEST(RandomWorld, RunsWithEffectsPlayAndTouch) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    Simulator sim(randomScenario(seed, true).scenario);
    int contact = 0;
    while (!sim.done()) contact += sim.next().in_contact ? 1 : 0;
    EXPECT_GT(contact, 0) << "seed " << seed << " never touched";
  }
}

// One effect alone (the campaign's --world-only): on in every run, the others off, and the same size as the
// full draw's where the full draw turns it on and the effects drawn before it off.
TEST(RandomWorld, OneEffectAloneIsOnInEveryRunWithTheFullDrawsSize) {
  int same_as_full = 0;
  for (unsigned seed = 1; seed <= 60; ++seed) {
    const WorldEffects full = randomScenario(seed, true).scenario.world;
    const WorldEffects creep = randomScenario(seed, true, WorldEffect::creep).scenario.world;
    EXPECT_TRUE(creep.viscoelastic.enabled()) << "seed " << seed;
    EXPECT_FALSE(creep.camera_shift.enabled() || creep.damage.enabled() || creep.light.enabled() ||
                 creep.drift.enabled())
        << "seed " << seed;
    if (full.viscoelastic.enabled()) {  // the first effect drawn: always the full draw's own
      EXPECT_EQ(creep.viscoelastic.relaxation, full.viscoelastic.relaxation);
      EXPECT_EQ(creep.viscoelastic.time_s, full.viscoelastic.time_s);
    }
    const WorldEffects shift = randomScenario(seed, true, WorldEffect::camera_shift).scenario.world;
    EXPECT_TRUE(shift.camera_shift.enabled()) << "seed " << seed;
    EXPECT_FALSE(shift.viscoelastic.enabled() || shift.damage.enabled() || shift.light.enabled() ||
                 shift.drift.enabled())
        << "seed " << seed;
    if (full.camera_shift.enabled() && !full.viscoelastic.enabled()) {  // the stream consumed alike before it
      ++same_as_full;
      EXPECT_EQ(shift.camera_shift.shift_px, full.camera_shift.shift_px);
      EXPECT_EQ(shift.camera_shift.at_s, full.camera_shift.at_s);
    }
    for (WorldEffect e : {WorldEffect::damage, WorldEffect::light, WorldEffect::drift}) {
      const WorldEffects w = randomScenario(seed, true, e).scenario.world;
      EXPECT_EQ(w.damage.enabled(), e == WorldEffect::damage);
      EXPECT_EQ(w.light.enabled(), e == WorldEffect::light);
      EXPECT_EQ(w.drift.enabled(), e == WorldEffect::drift);
      EXPECT_FALSE(w.viscoelastic.enabled() || w.camera_shift.enabled());
    }
  }
  EXPECT_GT(same_as_full, 5);
}
