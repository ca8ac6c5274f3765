// The whole MC in lockstep: high-level commands through the state machine make the simulated
// robot stand and walk (the path a real client's commands take, without the transport).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "loop/lockstep_client.hpp"
#include "control/locomotion/gait_table.hpp"
#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"
#include "loop/simulated_robot.hpp"
#include "mc_fixture.hpp"

namespace cerebellum {
namespace {

using testing::command;
using testing::lying_start;

TEST(McWalking, StandsThenTrotsForwardOnCommand) {
  Mc mc = make_simulated_mc(lying_start());
  LockstepClient client(mc);
  client.run(command(ModeId::RecoveryStand, 0), 3.0);
  EXPECT_EQ(mc.machine().status().mode, 12);
  EXPECT_EQ(mc.machine().status().order_process_bar, 100);
  const double x0 = mc.simulation().ground_truth().position[0];
  client.run(command(ModeId::Locomotion, 3, 0.5), 5.0);
  EXPECT_EQ(mc.machine().status().mode, 11);
  EXPECT_EQ(mc.machine().status().gait_id, 3);
  EXPECT_EQ(mc.machine().status().switch_status, SwitchStatus::Done);
  EXPECT_NEAR(mc.simulation().ground_truth().position[0] - x0, 2.5, 0.15 * 2.5);
  EXPECT_GT(mc.simulation().ground_truth().position[2], 0.22);
  // the trot's contact plan travels in the cycle record to the estimator
  EXPECT_TRUE(mc.loop().last_cycle().contact_plan.has_value());
}

TEST(McWalking, WalkingFromLyingIsBannedAndTheRobotStaysDown) {
  Mc mc = make_simulated_mc(lying_start());
  LockstepClient client(mc);
  client.run(command(ModeId::Locomotion, 3, 0.5), 1.0);
  EXPECT_EQ(mc.machine().status().mode, 0);
  EXPECT_EQ(mc.machine().status().switch_status, SwitchStatus::BanTransition);
  EXPECT_LT(mc.simulation().ground_truth().position[2], 0.2);
}

TEST(McWalking, ClientThatVanishesWhileWalkingGetsTheRobotDamped) {
  Mc mc = make_simulated_mc(lying_start());
  LockstepClient client(mc);
  client.run(command(ModeId::RecoveryStand, 0), 3.0);
  client.run(command(ModeId::Locomotion, 27, 0.3), 2.0);
  // silence: no heartbeat for 2 s
  for (int i = 0; i < 1000; ++i) mc.loop().tick();
  EXPECT_EQ(mc.machine().status().mode, 7);
  EXPECT_LT(mc.simulation().ground_truth().position[2], 0.2);
  const auto v = mc.simulation().ground_truth().velocity_world;
  EXPECT_LT(std::hypot(v[0], v[1]), 0.1);
}

TEST(McWalking, StopsAndStandsWhenAskedForTheStandGaitWhileRunning) {
  Mc mc = make_simulated_mc(lying_start());
  LockstepClient client(mc);
  client.run(command(ModeId::RecoveryStand, 0), 3.0);
  client.run(command(ModeId::Locomotion, 10, 1.2), 4.0);
  client.run(command(ModeId::Locomotion, 1), 3.0);
  const auto v = mc.simulation().ground_truth().velocity_world;
  EXPECT_LT(std::hypot(v[0], v[1]), 0.1);
  EXPECT_GT(mc.simulation().ground_truth().position[2], 0.22);
  EXPECT_EQ(mc.machine().status().gait_id, 1);
}

}  // namespace
}  // namespace cerebellum

namespace cerebellum {
namespace {

TEST(McWalking, QpStandServesTheStandGaitsWhenConfigured) {
  McConfig config = lying_start();
  config.locomotion_stand = LocomotionStand::Qp;
  Mc mc = make_simulated_mc(config);
  LockstepClient client(mc);
  client.run(command(ModeId::RecoveryStand, 0), 3.0);
  client.run(command(ModeId::Locomotion, 31), 2.0);
  EXPECT_EQ(mc.machine().status().mode, 11);
  EXPECT_EQ(mc.machine().status().gait_id, 31);
  // the QP stand plans no steps: the walking controller has not run a single MPC solve
  EXPECT_EQ(mc.walking().controller().telemetry().mpc_solves, 0u);
  EXPECT_FALSE(mc.loop().last_cycle().contact_plan.has_value());
  EXPECT_GT(mc.simulation().ground_truth().position[2], 0.2);
}

}  // namespace
}  // namespace cerebellum

namespace cerebellum {
namespace {

TEST(McWalking, ClimbsTheTenDegreeRamp) {
  McConfig config = lying_start();
  config.robot.model_path = std::string(CEREBELLUM_MODEL_DIR) + "/terrain_slope10.xml";
  Mc mc = make_simulated_mc(config);
  LockstepClient client(mc);
  client.run(command(ModeId::RecoveryStand, 0), 3.0);
  bool upright = true;
  client.run(command(ModeId::Locomotion, 27, 0.4), 16.0, [&](const CycleRecord& record) {
    upright &= std::abs(record.state.rpy.x()) < 0.5 && std::abs(record.state.rpy.y()) < 0.5;
  });
  EXPECT_TRUE(upright);
  // the ramp rises 0.52 m over 3 m from x = 1 m; the trunk ends on the plateau
  EXPECT_GT(mc.simulation().ground_truth().position[0], 4.0);
  EXPECT_GT(mc.simulation().ground_truth().position[2], 0.5 + 0.2);
}

}  // namespace
}  // namespace cerebellum

namespace cerebellum {
namespace {

struct LowStepWalk {
  double forward_m = 0.0;
  double lowest_trunk_m = 1.0;
  double highest_foot_clearance_m = 0.0;  // over the feet and the walk's last 2 s
  bool upright = true;
};

// trot 3 at 0.3 m/s for 4 s with the given step height; feet measured on the ground truth trunk
LowStepWalk trot_with_step_height(float step_height_m) {
  Mc mc = make_simulated_mc(lying_start());
  LockstepClient client(mc);
  client.run(command(ModeId::RecoveryStand, 0), 3.0);
  HighLevelCommand walk = command(ModeId::Locomotion, 3, 0.3);
  walk.step_height = {step_height_m, step_height_m};
  LowStepWalk result;
  const double x0 = mc.simulation().ground_truth().position[0];
  const double t0 = mc.loop().last_cycle().state.time_s;
  client.run(walk, 4.0, [&](const CycleRecord& record) {
    const GroundTruth truth = mc.simulation().ground_truth();
    result.lowest_trunk_m = std::min(result.lowest_trunk_m, truth.position[2]);
    result.upright &= std::abs(record.state.rpy.x()) < 0.5 && std::abs(record.state.rpy.y()) < 0.5;
    if (record.state.time_s - t0 < 2.0) return;
    const Eigen::Quaterniond body_to_world(truth.quat[0], truth.quat[1], truth.quat[2], truth.quat[3]);
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      const double foot_z = truth.position[2] + (body_to_world * record.state.foot_position_body[leg]).z();
      result.highest_foot_clearance_m = std::max(result.highest_foot_clearance_m, foot_z - robot::kFootRadius);
    }
  });
  result.forward_m = mc.simulation().ground_truth().position[0] - x0;
  return result;
}

TEST(McWalking, TrotsWithAFiveMillimetreStepHeightAndTheSwingFollowsIt) {
  const LowStepWalk low = trot_with_step_height(0.005f);
  EXPECT_TRUE(low.upright);
  EXPECT_GT(low.forward_m, 0.9);  // 4 s at 0.3 m/s, starting from a stand
  EXPECT_GT(low.lowest_trunk_m, 0.22);
  EXPECT_GT(low.highest_foot_clearance_m, 0.001);
  EXPECT_LT(low.highest_foot_clearance_m, 0.008);  // not the gait's default 6 cm
  const LowStepWalk mid = trot_with_step_height(0.03f);
  EXPECT_NEAR(mid.highest_foot_clearance_m, 0.03, 0.005);
}

TEST(McWalking, AZeroStepHeightWalksAtTheFiveMillimetreFloor) {
  const LowStepWalk zero = trot_with_step_height(0.0f);
  EXPECT_TRUE(zero.upright);
  EXPECT_GT(zero.forward_m, 0.9);
  EXPECT_GT(zero.lowest_trunk_m, 0.22);
  EXPECT_LT(zero.highest_foot_clearance_m, 0.008);
}

TEST(McWalking, TheVelocityEstimateStaysWithTheTrunkWhileAFastTurningFlyingTrotBouncesOnItsFeet) {
  // the soak's commands before a fall (seed 335 at 92 s): the flying trot from a slow trot to
  // 1.6 m/s with 0.4 m/s sideways, turning. Its stance pairs bounce off the ground while the plan
  // says stance; their legs, pushing in the air, pulled the estimate off the truth, by 4.2 m/s in
  // this run, and the robot fell. Now the largest error is 0.36 m/s
  Mc mc = make_simulated_mc(lying_start());
  LockstepClient client(mc);
  client.run(command(ModeId::RecoveryStand, 0), 3.0);
  client.run(high_level_command(ModeId::Locomotion, kSlowTrotGaitId, 0.02, -0.11, -0.16), 2.0);
  double largest_error_m_s = 0.0;
  double fastest_m_s = 0.0;
  bool upright = true;
  client.run(high_level_command(ModeId::Locomotion, kFlyingTrotGaitId, 1.59, 0.42, -1.02), 4.0,
             [&](const CycleRecord& record) {
               const GroundTruth truth = mc.simulation().ground_truth();
               const Eigen::Vector2d true_velocity(truth.velocity_world[0], truth.velocity_world[1]);
               largest_error_m_s =
                   std::max(largest_error_m_s, (record.state.velocity_world.head<2>() - true_velocity).norm());
               fastest_m_s = std::max(fastest_m_s, true_velocity.norm());
               upright &= truth.position[2] > 0.15;
             });
  EXPECT_TRUE(upright);
  EXPECT_GT(fastest_m_s, 1.3);
  EXPECT_LT(largest_error_m_s, 0.5);
}

}  // namespace
}  // namespace cerebellum
