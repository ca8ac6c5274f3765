// Mode 11's stands under a shove, the whole MC in lockstep on the simulation's truth: the stand
// with push recovery (gait 1) steps to catch a push its planted feet cannot take and stands again
// where it came to rest; the stand without (gait 31) keeps every foot down.
#include <gtest/gtest.h>

#include <cmath>

#include "app/lockstep_client.hpp"
#include "app/simulated_robot.hpp"
#include "control/locomotion/gait_table.hpp"

namespace cerebellum {
namespace {

double tilt_rad(const GroundTruth& truth) {
  const auto& q = truth.quat;
  return std::acos(std::clamp(1.0 - 2.0 * (q[1] * q[1] + q[2] * q[2]), -1.0, 1.0));
}

struct ShoveOutcome {
  double largest_tilt_rad = 0.0;
  bool a_foot_lifted = false;
  int final_mode = 0;
  double final_speed_m_s = 0.0;
  bool all_feet_down_at_the_end = false;
  double moved_m = 0.0;
};

// stands up, holds the stand gait 2 s, pushes the trunk sideways (world +y, or -y from the left)
// with impulse_n_s spread over push_s, and watches for settle_s
ShoveOutcome shove(int gait_id, double impulse_n_s, double push_s, double settle_s, double direction_y = 1.0) {
  McConfig config = default_config();
  config.startup = Startup::Off;
  Mc mc = make_simulated_mc(config);
  LockstepClient client(mc);
  client.run(high_level_command(ModeId::RecoveryStand, 0), 3.0);
  const HighLevelCommand stand = high_level_command(ModeId::Locomotion, gait_id);
  client.run(stand, 2.0);
  const double y0 = mc.simulation().ground_truth().position[1];
  mc.simulation().request_force_pulse({{0.0, direction_y * impulse_n_s / push_s, 0.0}, push_s});
  ShoveOutcome outcome;
  client.run(stand, push_s + settle_s, [&](const CycleRecord&) {
    const GroundTruth truth = mc.simulation().ground_truth();
    outcome.largest_tilt_rad = std::max(outcome.largest_tilt_rad, tilt_rad(truth));
    for (bool contact : truth.foot_contact) outcome.a_foot_lifted |= !contact;
  });
  const GroundTruth truth = mc.simulation().ground_truth();
  outcome.final_mode = mc.machine().status().mode;
  outcome.final_speed_m_s = std::hypot(truth.velocity_world[0], truth.velocity_world[1]);
  outcome.all_feet_down_at_the_end =
      truth.foot_contact[0] && truth.foot_contact[1] && truth.foot_contact[2] && truth.foot_contact[3];
  outcome.moved_m = direction_y * (truth.position[1] - y0);
  return outcome;
}

TEST(McPushRecovery, TheStandWithPushRecoveryStepsUnderAShoveThatTopplesPlantedFeetAndStandsAgainWithin3s) {
  // 15 N s sideways over 0.5 s: 30 N at the trunk's height tips the planted stance over its left
  // feet (gait 31 fell in all five runs of the push sweep, docs/benchmarks.md)
  const ShoveOutcome outcome = shove(kStandGaitId, 15.0, 0.5, 3.0);
  EXPECT_TRUE(outcome.a_foot_lifted);
  EXPECT_LT(outcome.largest_tilt_rad, 0.5);
  EXPECT_EQ(outcome.final_mode, 11);
  EXPECT_LT(outcome.final_speed_m_s, 0.05);
  EXPECT_TRUE(outcome.all_feet_down_at_the_end);
  // it stands where it came to rest, along the push, not back where it was pushed from
  EXPECT_GT(outcome.moved_m, 0.1);
}

TEST(McPushRecovery, TheStandWithPushRecoveryCatchesA20NsSidewaysShoveOverHalfASecond) {
  // 40 N for 0.5 s: the catching footholds reach far out under a rolled trunk (they are kept
  // inside the interface's foot workspace, so the footpos watch does not end the recovery)
  const ShoveOutcome outcome = shove(kStandGaitId, 20.0, 0.5, 3.0);
  EXPECT_LT(outcome.largest_tilt_rad, 0.6);
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
