// Mode 11's stands under the longest shoves, the whole MC in lockstep on the simulation's truth: a
// steady push the planted feet hold until they must step, 25 N s from the left or the front, 20 N s
// from the front or the tail, and the stand without push recovery under a steady 25 N push. Up to
// a minute and a half each under the sanitizers: long, left out of the sanitized stage, whose
// mc_push_recovery_test.cpp cases take the same code paths with shorter shoves.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "control/locomotion/gait_table.hpp"
#include "mc_push_recovery_shove.hpp"

namespace cerebellum {
namespace {

using push_recovery_testing::shove;
using push_recovery_testing::ShoveOutcome;

TEST(McPushRecovery, TheStandWithPushRecoveryKeepsItsFeetPlantedUntilASteadyShoveFromTheSideHasToBeStepped) {
  // 50 N for 0.5 s at moments of the push sweep (docs/benchmarks.md) where stepping as soon as the
  // trunk passed 0.3 m/s fell (six of these eight runs): the trotting pair took the roll over one
  // foot per side while the force still acted. Four planted feet hold it until 0.45 m/s or the
  // capture point is near their edge
  for (const double side : {1.0, -1.0}) {
    for (const double stand_extra_s : {0.036, 0.108, 0.144, 0.324}) {
      const ShoveOutcome outcome = shove(kStandGaitId, 25.0, 0.5, 3.0, {0.0, side}, stand_extra_s);
      EXPECT_LT(outcome.largest_tilt_rad, 0.6) << side << " at +" << stand_extra_s << " s";
      EXPECT_EQ(outcome.final_mode, 11) << side << " at +" << stand_extra_s << " s";
      EXPECT_LT(outcome.final_speed_m_s, 0.05) << side << " at +" << stand_extra_s << " s";
    }
  }
}

TEST(McPushRecovery, TheStandWithPushRecoveryCatchesA25NsShoveFromTheLeftOrFrontWithoutTrippingOverItsSideSteps) {
  // moments of the push sweep where the catching trot, stepping sideways with walking's k, landed
  // its feet far out under a body moving left at 1-1.9 m/s and tripped it over the diagonal (the
  // trunk rolled past 0.6 rad), and where 50 N toward the front ended in the footpos watch
  struct Case {
    std::array<double, 2> direction;
    double stand_extra_s;
  };
  for (const Case& c :
       {Case{{0.0, 1.0}, 0.018}, Case{{0.0, 1.0}, 0.09}, Case{{0.0, 1.0}, 0.18}, Case{{1.0, 0.0}, 0.0}}) {
    const ShoveOutcome outcome = shove(kStandGaitId, 25.0, 0.5, 3.0, c.direction, c.stand_extra_s);
    const std::string at = "toward (" + std::to_string(c.direction[0]) + ", " + std::to_string(c.direction[1]) +
                           ") at +" + std::to_string(c.stand_extra_s) + " s";
    EXPECT_LT(outcome.largest_tilt_rad, 0.6) << at;
    EXPECT_EQ(outcome.final_mode, 11) << at;
    EXPECT_LT(outcome.final_speed_m_s, 0.05) << at;
    EXPECT_TRUE(outcome.all_feet_down_at_the_end) << at;
  }
}

TEST(McPushRecovery, TheStandWithPushRecoveryTakesA20NsShoveFromTheFrontOrTheTailAndStandsAgainWithin3s) {
  // 40 N along the body for 0.5 s: with gait 3 as the catching trot, the pitched trunk put a
  // planted foot outside the interface's workspace and the footpos watch damped the robot
  for (const double along : {1.0, -1.0}) {
    const ShoveOutcome outcome = shove(kStandGaitId, 20.0, 0.5, 3.0, {along, 0.0});
    EXPECT_LT(outcome.largest_tilt_rad, 0.6) << along;
    EXPECT_EQ(outcome.final_mode, 11) << along;
    EXPECT_LT(outcome.final_speed_m_s, 0.05) << along;
    EXPECT_TRUE(outcome.all_feet_down_at_the_end) << along;
  }
}

TEST(McPushRecovery, TheStandWithoutPushRecoveryHoldsASteady25NPushFromTheSideOverItsPlantedFeet) {
  // 25 N at the trunk's height for 2 s: below the ~36 N that tips the planted stance over its feet,
  // so it leans against it and stays where it stands (it used to drift off its feet and fall; the
  // feet on the far side carry little and may flicker off the ground)
  const ShoveOutcome outcome = shove(kStandWithoutPushRecoveryGaitId, 50.0, 2.0, 2.0);
  EXPECT_LT(outcome.largest_tilt_rad, 0.2);
  EXPECT_EQ(outcome.final_mode, 11);
  EXPECT_LT(outcome.final_speed_m_s, 0.05);
  EXPECT_TRUE(outcome.all_feet_down_at_the_end);
  EXPECT_LT(std::abs(outcome.moved_m), 0.1);
}

}  // namespace
}  // namespace cerebellum
