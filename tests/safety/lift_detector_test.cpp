// The lift decision on synthetic states: unloaded feet, support and rise together make a lift;
// enough loaded feet held long enough make a landing.
#include "safety/lift_detector.hpp"

#include <gtest/gtest.h>

namespace cerebellum {
namespace {

TEST(LiftDetection, NeedsUnloadedFeetSupportAndRiseTogether) {
  LiftWatch watch;
  RobotState s;
  s.contact = {0, 0, 0, 0};
  // supported but not rising (lying on the belly): never
  for (int i = 0; i < 500; ++i, s.time_s += 0.002) EXPECT_FALSE(detect_lifted(s, watch));
  // rising at 2 m/s^2 with unloaded feet: after the rise threshold and 0.1 s unloaded
  watch = LiftWatch{};
  s.accel_world = {0.0, 0.0, 2.0};
  double lifted_at = -1.0;
  const double start = s.time_s;
  for (int i = 0; i < 500 && lifted_at < 0.0; ++i, s.time_s += 0.002) {
    if (detect_lifted(s, watch)) lifted_at = s.time_s - start;
  }
  // 0.2 m/s at 2 m/s^2 (less the leak) takes a little over 0.1 s
  EXPECT_GT(lifted_at, 0.098);
  EXPECT_LT(lifted_at, 0.15);
  // one loaded foot resets the count
  watch = LiftWatch{};
  s.contact = {1, 0, 0, 0};
  for (int i = 0; i < 500; ++i, s.time_s += 0.002) EXPECT_FALSE(detect_lifted(s, watch));
}

TEST(LiftDetection, LandsWithThreeLoadedFeetHeldForATenthOfASecond) {
  LiftWatch watch;
  RobotState s;
  s.contact = {1, 1, 0, 0};
  for (int i = 0; i < 100; ++i, s.time_s += 0.002) EXPECT_FALSE(detect_landed(s, watch));
  s.contact = {1, 1, 1, 0};
  int ticks = 0;
  while (!detect_landed(s, watch) && ticks < 1000) ++ticks, s.time_s += 0.002;
  EXPECT_NEAR(ticks, 50, 1);
}

TEST(LiftDetection, AFreshWatchStartsItsClockAtTheFirstTick) {
  // the first tick only starts the clock: a watch reset while lifted needs the full hold again
  LiftWatch watch;
  RobotState s;
  s.contact = {1, 1, 1, 1};
  s.time_s = 100.0;
  EXPECT_FALSE(detect_landed(s, watch));
  EXPECT_EQ(watch.loaded_s, 0.0);
  s.time_s += 0.05;
  EXPECT_FALSE(detect_landed(s, watch));
  EXPECT_NEAR(watch.loaded_s, 0.05, 1e-12);
}

}  // namespace
}  // namespace cerebellum
