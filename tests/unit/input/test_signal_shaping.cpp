#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "input/input_filter.hpp"
#include "input/input_shaping.hpp"
#include "input/press_button.hpp"

using namespace onetip;
using namespace onetip::input;

namespace {
Input6 all(double v) { return Input6::fromArray({v, v, v, v, v, v}); }
}  // namespace

TEST(Filters, MovingAverageIsTheMeanOfTheLastWindow) {
  MovingAverageFilter f(5);
  double out = 0;
  for (int k = 1; k <= 8; ++k) out = f.apply(all(k), k / 30.0).dx;
  EXPECT_DOUBLE_EQ(out, (4 + 5 + 6 + 7 + 8) / 5.0);
  f.reset();
  EXPECT_DOUBLE_EQ(f.apply(all(3), 0).yaw, 3);
}

TEST(Filters, OneEuroLagsLessThanTheMovingAverageOnARampAndSettlesAtRest) {
  MovingAverageFilter ma(5);
  OneEuroFilter oe(1.0, 0.5, 1.0);
  double lag_ma = 0, lag_oe = 0;
  for (int k = 0; k <= 60; ++k) {
    const double t = k / 30.0, x = 3.0 * t;  // 3 mm/s ramp
    lag_ma = x - ma.apply(all(x), t).dx;
    lag_oe = x - oe.apply(all(x), t).dx;
  }
  EXPECT_NEAR(lag_ma, 2 * 3.0 / 30.0, 1e-9);  // two frames
  EXPECT_LT(lag_oe, lag_ma);
  double y = 0;
  for (int k = 61; k <= 200; ++k) y = oe.apply(all(6.0), k / 30.0).dx;
  EXPECT_NEAR(y, 6.0, 1e-3);
}

TEST(Shaping, DeadZoneThenGainPerAxis) {
  InputShaping s;
  s.dead_zone = {0.1, 0, 0, 1.0, 0, 0};
  s.gain = {2, 1, 1, 0.5, 1, -1};
  const Input6 out = s.apply(Input6{0.05, 0.2, 0.3, -3.0, 4.0, 5.0});
  EXPECT_DOUBLE_EQ(out.dx, 0.0);   // inside the dead zone
  EXPECT_DOUBLE_EQ(out.dy, 0.2);
  EXPECT_DOUBLE_EQ(out.yaw, -1.0); // (3 - 1) * 0.5, sign kept
  EXPECT_DOUBLE_EQ(out.roll, -5.0);
  s.dead_zone[2] = -1;
  EXPECT_THROW(s.validate(), InputError);
}

TEST(PressButton, HysteresisPreventsChatter) {
  PressButton b({1.5, 1.0});
  EXPECT_FALSE(b.update(1.4));
  EXPECT_TRUE(b.update(1.6));   // pressed
  EXPECT_FALSE(b.update(1.2));  // still pressed inside the band
  EXPECT_FALSE(b.update(1.55));
  EXPECT_TRUE(b.update(0.9));   // released
  EXPECT_FALSE(b.pressed());
  EXPECT_THROW(PressButton({1.0, 1.0}), InputError);
}

TEST(Filters, OptionsAreValidated) {
  InputFilterOptions o;
  o.kind = FilterKind::moving_average;
  o.window = 0;
  EXPECT_THROW(makeInputFilter(o), InputError);
  o = {};
  EXPECT_EQ(makeInputFilter(o), nullptr);  // none
}
