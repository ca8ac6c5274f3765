#include "control/locomotion/slip_watch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace cerebellum {
namespace {

// one stance of 20 ticks of a leg at this speed in its middle (and a fast touchdown and lift-off,
// which the window leaves out), then a tick in the air that ends it
void stance(SlipWatch& watch, std::size_t leg, double mid_speed_m_s) {
  for (int t = 0; t < 20; ++t) {
    const double phase = t / 19.0;
    const bool edge = phase < 0.15 || phase > 0.95;
    watch.observe(leg, true, phase, edge ? 1.0 : mid_speed_m_s);
  }
  watch.observe(leg, false, 0.0, 0.0);
}

TEST(SlipWatch, FeetThatHoldKeepTheGroundNotSlipperyThoughTouchdownsAreFast) {
  SlipWatch watch;
  for (int s = 0; s < 200; ++s) stance(watch, s % kNumLegs, 0.02);
  EXPECT_FALSE(watch.slippery());
  EXPECT_EQ(watch.telemetry().stances_observed, 200u);
  EXPECT_EQ(watch.telemetry().stances_slipped, 0u);
}

TEST(SlipWatch, AThirdOfStancesSlidingMarkTheGroundSlipperyAndHoldingFeetClearItAgain) {
  SlipWatch watch;
  for (int s = 0; s < 60; ++s) stance(watch, s % kNumLegs, s % 3 == 0 ? 0.3 : 0.02);
  EXPECT_TRUE(watch.slippery());
  EXPECT_NEAR(watch.slip_share(), 1.0 / 3.0, 0.12);
  EXPECT_EQ(watch.telemetry().slippery_entries, 1u);
  for (int s = 0; s < 60; ++s) stance(watch, s % kNumLegs, 0.02);
  EXPECT_FALSE(watch.slippery());
}

TEST(SlipWatch, AShareBetweenItsTwoThresholdsKeepsWhatTheGroundWas) {
  SlipWatchConfig config;
  SlipWatch watch(config);
  // one slip in eight: 12.5 %, between leave (8 %) and enter (16 %)
  for (int s = 0; s < 200; ++s) stance(watch, 0, s % 8 == 0 ? 0.3 : 0.02);
  EXPECT_FALSE(watch.slippery());
  EXPECT_EQ(watch.telemetry().slippery_entries, 0u);
}

TEST(SlipWatch, AStanceCutShortAndANonFiniteSpeedAreNoObservation) {
  SlipWatch watch;
  watch.observe(0, true, 0.5, 0.3);
  watch.observe(0, true, 0.55, 0.3);
  watch.observe(0, false, 0.0, 0.0);
  for (int t = 0; t < 20; ++t) watch.observe(1, true, t / 19.0, std::numeric_limits<double>::quiet_NaN());
  watch.observe(1, false, 0.0, 0.0);
  EXPECT_EQ(watch.telemetry().stances_observed, 0u);
  EXPECT_EQ(watch.slip_share(), 0.0);
}

TEST(SlipWatch, AWindowOutsideTheStanceOrThresholdsTheWrongWayRoundAreRefused) {
  SlipWatchConfig window;
  window.window_start_phase = 0.9;
  window.window_end_phase = 0.2;
  EXPECT_THROW(SlipWatch{window}, std::invalid_argument);
  SlipWatchConfig thresholds;
  thresholds.leave_share = 0.3;
  EXPECT_THROW(SlipWatch{thresholds}, std::invalid_argument);
}

}  // namespace
}  // namespace cerebellum
