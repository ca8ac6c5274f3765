// Mode 11's stands under a shove, the whole MC in lockstep on the simulation's truth: the stand
// with push recovery (gait 1) steps to catch a push its planted feet cannot take and stands again
// where it came to rest; the stand without (gait 31) keeps every foot down. The longest shoves
// (a steady push, every side) are in mc_push_recovery_long_test.cpp.
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

TEST(McPushRecovery, TheStandWithPushRecoveryStepsUnderA20NsSidewaysShoveThatTopplesPlantedFeetAndStandsAgainWithin3s) {
  // 40 N sideways for 0.5 s tips the planted stance over its feet (gait 31 fell in all five runs
  // of the push sweep, docs/benchmarks.md); the catching footholds reach far out under a rolled
  // trunk (kept inside the interface's foot workspace, so the footpos watch does not end it)
  const ShoveOutcome outcome = shove(kStandGaitId, 20.0, 0.5, 3.0);
  EXPECT_TRUE(outcome.a_foot_lifted);
  EXPECT_LT(outcome.largest_tilt_rad, 0.6);
  EXPECT_EQ(outcome.final_mode, 11);
  EXPECT_LT(outcome.final_speed_m_s, 0.05);
  EXPECT_TRUE(outcome.all_feet_down_at_the_end);
  // it stands where it came to rest, along the push, not back where it was pushed from
  EXPECT_GT(outcome.moved_m, 0.1);
}

TEST(McPushRecovery, TheStandWithPushRecoveryCatchesA25NsShoveFromEitherSideAndStandsAgainWithin3s) {
  // 50 N for 0.5 s: past both the planted stance's tipping force (~36 N) and what friction lets
  // the feet hold back (~34 N), so it must step while the force still acts. It fell without either
  // of two changes: the velocity estimate no longer trusts the feet the shove tipped off the
  // ground, and the trot begins with the diagonal that catches a body moving toward that side
  // (before, the same diagonal began whichever way the body moved)
  for (const double side : {1.0, -1.0}) {
    const ShoveOutcome outcome = shove(kStandGaitId, 25.0, 0.5, 3.0, {0.0, side});
    EXPECT_LT(outcome.largest_tilt_rad, 0.6) << side;
    EXPECT_EQ(outcome.final_mode, 11) << side;
    EXPECT_LT(outcome.final_speed_m_s, 0.05) << side;
    EXPECT_TRUE(outcome.all_feet_down_at_the_end) << side;
    EXPECT_GT(outcome.moved_m, 0.1) << side;
  }
}

TEST(McPushRecovery, TheVelocityEstimateFollowsTheTrunkWhileAShoveTipsItOffItsFarFeet) {
  // the shove lifts the far feet while the stand still plans them down: moving with the trunk,
  // they reported it at rest, the filter's gate kept them and refused the planted feet, and the
  // estimate read 0.05 m/s for a true 0.7 (largest error 0.86 m/s). A stand now plans no
  // contacts: the estimator judges its feet by their load
  const ShoveOutcome outcome = shove(kStandGaitId, 25.0, 0.5, 0.5);
  EXPECT_LT(outcome.largest_velocity_error_m_s, 0.4);
}

TEST(McPushRecovery, TheStandWithPushRecoveryTakesA15NsShoveBackwardAndStaysInTheMode) {
  // 30 N toward its tail for 0.5 s: the stand holds the trunk over its feet; when it drifted
  // with the push, the recovery steps pitched it until a foot left the interface's workspace and
  // the footpos watch damped the joints (mode 7) in all five runs of the push sweep
  const ShoveOutcome outcome = shove(kStandGaitId, 15.0, 0.5, 3.0, {-1.0, 0.0});
  EXPECT_LT(outcome.largest_tilt_rad, 0.3);
  EXPECT_EQ(outcome.final_mode, 11);
  EXPECT_LT(outcome.final_speed_m_s, 0.05);
  EXPECT_TRUE(outcome.all_feet_down_at_the_end);
}

TEST(McPushRecovery, TheStandWithoutPushRecoveryKeepsEveryFootDownUnderAShoveItCanLeanAgainst) {
  const ShoveOutcome outcome = shove(kStandWithoutPushRecoveryGaitId, 4.0, 0.5, 2.0);
  EXPECT_FALSE(outcome.a_foot_lifted);
  EXPECT_LT(outcome.largest_tilt_rad, 0.2);
  EXPECT_EQ(outcome.final_mode, 11);
  EXPECT_LT(outcome.final_speed_m_s, 0.05);
}

}  // namespace
}  // namespace cerebellum
