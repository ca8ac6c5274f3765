// The two-leg stand (mode 64) through the whole MC in lockstep, judged on the simulation's ground
// truth: the robot rises onto its hind feet with the trunk near vertical, holds it for the rest of
// the command's duration, comes down and stands where a stand stands; commands that would drop
// it are refused while it is up, damping still stops it, a silent client is damped only once it
// is back on four feet, a shove it cannot catch ends in damping, not flailing, and a link a few
// ticks slow each way (backend/latent_link_backend, as on the stacked pair) changes none of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "loop/lockstep_client.hpp"
#include "loop/simulated_robot.hpp"
#include "backend/sim_fixture.hpp"
#include "core/robot_model.hpp"
#include "mc_fixture.hpp"

namespace cerebellum {
namespace {

using testing::truth_elevation;

// what one two-leg stand did, on the truth
struct Outcome {
  double highest_elevation_rad = 0.0;
  double upright_s = 0.0;  // the trunk above 1.2 rad on the hind feet alone
  bool front_feet_down_while_upright = false;
  bool hind_foot_up_while_upright = false;
  double peak_torque_nm = 0.0;
  bool reported_64 = true;  // every response while it ran said 64 / 0
  bool progress_never_fell = true;
  double done_after_s = -1.0;  // the response's bar reached 100
};

McConfig with_latency(McConfig config, LinkLatencyTicks latency) {
  config.simulated_link_latency = latency;
  return config;
}

struct TwoLegRun {
  explicit TwoLegRun(bool noise = false, unsigned seed = 0, LinkLatencyTicks latency = {})
      : mc(make_simulated_mc(with_latency(testing::lying_start(noise, seed), latency))), client(mc) {
    client.run(high_level_command(ModeId::RecoveryStand, 0), 3.0);
    // the pose hold the seed's example is in when it asks for the two-leg stand
    client.run(high_level_command(ModeId::PoseControl, 3), 1.0);
    stand_height_m = mc.simulation().ground_truth().position[2];
  }

  Outcome stand_on_two_legs(double seconds, int duration_ms = 0) {
    HighLevelCommand command = high_level_command(ModeId::TwoLegStand, 0);
    command.duration = duration_ms;
    Outcome outcome;
    int last_bar = 0;
    const double start_s = mc.simulation().time_s();
    client.run(command, seconds, [&](const CycleRecord&) { observe(outcome, last_bar, start_s); });
    return outcome;
  }

  void observe(Outcome& outcome, int& last_bar, double start_s) {
    const GroundTruth g = mc.simulation().ground_truth();
    const double elevation = truth_elevation(g);
    outcome.highest_elevation_rad = std::max(outcome.highest_elevation_rad, elevation);
    if (elevation > 1.2) {
      outcome.upright_s += mc.loop().period_s();
      outcome.front_feet_down_while_upright |= g.foot_contact[0] || g.foot_contact[1];
      outcome.hind_foot_up_while_upright |= !g.foot_contact[2] || !g.foot_contact[3];
    }
    for (double tau : g.tau) outcome.peak_torque_nm = std::max(outcome.peak_torque_nm, std::abs(tau));
    const HighLevelStatus& status = mc.machine().status();
    outcome.reported_64 &= status.mode == 64 && status.gait_id == 0;
    outcome.progress_never_fell &= status.order_process_bar >= last_bar;
    last_bar = status.order_process_bar;
    if (status.order_process_bar == 100 && outcome.done_after_s < 0.0) {
      outcome.done_after_s = mc.simulation().time_s() - start_s;
    }
  }

  Mc mc;
  LockstepClient client;
  double stand_height_m = 0.0;
};

void expect_standing_again(TwoLegRun& run, ModeId mode = ModeId::TwoLegStand) {
  const GroundTruth g = run.mc.simulation().ground_truth();
  const Eigen::Vector3d rpy = testing::truth_rpy(g);
  EXPECT_NEAR(g.position[2], run.stand_height_m, 0.01);
  EXPECT_LT(std::abs(rpy.x()), 0.05);
  EXPECT_LT(std::abs(rpy.y()), 0.05);
  for (bool contact : g.foot_contact) EXPECT_TRUE(contact);
  const HighLevelStatus& status = run.mc.machine().status();
  EXPECT_EQ(status.mode, static_cast<int>(mode));
  EXPECT_EQ(status.order_process_bar, 100);
  EXPECT_EQ(status.switch_status, SwitchStatus::Done);
}

TEST(McTwoLegStand, RisesOntoItsHindFeetHoldsTheTrunkNearVerticalAndStandsAgain) {
  TwoLegRun run;
  const Outcome outcome = run.stand_on_two_legs(12.0);
  EXPECT_GT(outcome.highest_elevation_rad, 1.3);
  EXPECT_LT(outcome.highest_elevation_rad, robot::kPi / 2.0);  // never past vertical
  EXPECT_GT(outcome.upright_s, 1.0);
  EXPECT_FALSE(outcome.front_feet_down_while_upright);
  EXPECT_FALSE(outcome.hind_foot_up_while_upright);
  EXPECT_LE(outcome.peak_torque_nm, robot::kTorqueMaxNm + 1e-9);
  EXPECT_TRUE(outcome.reported_64);
  EXPECT_TRUE(outcome.progress_never_fell);
  // the reference's duration (> 8700 ms) and the seed's example's 10 s wait
  EXPECT_GT(outcome.done_after_s, 8.7);
  EXPECT_LT(outcome.done_after_s, 10.0);
  expect_standing_again(run);
}

TEST(McTwoLegStand, RisesHoldsAndStandsAgainThroughALinkTwoTicksSlowEachWay) {
  TwoLegRun run(false, 0, LinkLatencyTicks{2, 2});
  const Outcome outcome = run.stand_on_two_legs(12.0);
  EXPECT_GT(outcome.highest_elevation_rad, 1.3);
  EXPECT_GT(outcome.upright_s, 1.0);
  EXPECT_FALSE(outcome.front_feet_down_while_upright);
  EXPECT_FALSE(outcome.hind_foot_up_while_upright);
  expect_standing_again(run);
}

TEST(McTwoLegStand, HoldsALongCommandUprightThroughALinkFourTicksSlowEachWay) {
  // 16 ms from a state to its command's effect: beyond the stacked pair's usual 2-6 ms
  TwoLegRun run(false, 0, LinkLatencyTicks{4, 4});
  const Outcome outcome = run.stand_on_two_legs(16.0, 14000);
  EXPECT_GT(outcome.upright_s, 5.0);
  EXPECT_FALSE(outcome.front_feet_down_while_upright);
  EXPECT_FALSE(outcome.hind_foot_up_while_upright);
  EXPECT_GT(outcome.done_after_s, 14.0);
  expect_standing_again(run, ModeId::PoseControl);
}

TEST(McTwoLegStand, HoldsTheUprightPoseForTheRestOfALongerCommand) {
  TwoLegRun run;
  const Outcome outcome = run.stand_on_two_legs(16.0, 14000);
  EXPECT_GT(outcome.upright_s, 5.0);
  EXPECT_FALSE(outcome.front_feet_down_while_upright);
  EXPECT_GT(outcome.done_after_s, 14.0);
  // a timed entry is followed by the reference's hold, the pose hold (21/3)
  expect_standing_again(run, ModeId::PoseControl);
}

TEST(McTwoLegStand, AnotherModeIsRefusedWhileUprightAndDampingStillStopsIt) {
  TwoLegRun run;
  run.stand_on_two_legs(5.5, 12000);  // up on the hind feet, its hold lasting well past the checks
  ASSERT_GT(truth_elevation(run.mc.simulation().ground_truth()), 1.2);
  run.client.run(high_level_command(ModeId::PoseControl, 0), 0.5);
  EXPECT_EQ(run.mc.machine().status().mode, 64);
  EXPECT_EQ(run.mc.machine().status().switch_status, SwitchStatus::BanTransition);
  EXPECT_GT(truth_elevation(run.mc.simulation().ground_truth()), 1.2);
  run.client.run(high_level_command(ModeId::PureDamper, 0), 0.1);
  EXPECT_EQ(run.mc.machine().status().mode, 7);
}

TEST(McTwoLegStand, AClientThatFallsSilentUprightIsDampedOnlyOnceTheRobotIsOnFourFeet) {
  TwoLegRun run;
  run.stand_on_two_legs(5.5);
  ASSERT_GT(truth_elevation(run.mc.simulation().ground_truth()), 1.2);
  // no more messages: the heartbeat times out while the robot is up
  bool damped_upright = false;
  double lowest_m = 1.0;
  for (int tick = 0; tick < 3000; ++tick) {
    run.mc.loop().tick();
    const GroundTruth g = run.mc.simulation().ground_truth();
    damped_upright |= run.mc.machine().status().mode == 7 && truth_elevation(g) > 0.5;
    lowest_m = std::min(lowest_m, g.position[2]);
  }
  EXPECT_FALSE(damped_upright);
  EXPECT_EQ(run.mc.machine().status().mode, 7);  // the get-down protection, once down
}

TEST(McTwoLegStand, AShoveItCannotCatchUprightEndsInDampingAndTheRecoveryStandRightsIt) {
  TwoLegRun run;
  run.stand_on_two_legs(5.5);
  ASSERT_GT(truth_elevation(run.mc.simulation().ground_truth()), 1.2);
  run.mc.simulation().request_force_pulse(ForcePulse{{-60.0, 0.0, 0.0}, 0.3});
  bool damped = false;
  run.client.run(high_level_command(ModeId::TwoLegStand, 0), 2.0, [&](const CycleRecord&) {
    damped |= run.mc.machine().status().switch_status == SwitchStatus::HighDamping;
  });
  EXPECT_TRUE(damped);
  run.client.run(high_level_command(ModeId::RecoveryStand, 0), 6.0);
  const Eigen::Vector3d rpy = testing::truth_rpy(run.mc.simulation().ground_truth());
  EXPECT_LT(std::abs(rpy.y()), 0.1);
  EXPECT_GT(run.mc.simulation().ground_truth().position[2], 0.2);
}

TEST(McTwoLegStand, OnlyGaitZeroIsAccepted) {
  TwoLegRun run;
  run.client.run(high_level_command(ModeId::TwoLegStand, 1), 0.5);
  EXPECT_EQ(run.mc.machine().status().mode, static_cast<int>(ModeId::PoseControl));
  EXPECT_EQ(run.mc.machine().status().switch_status, SwitchStatus::BanTransition);
}

}  // namespace
}  // namespace cerebellum
