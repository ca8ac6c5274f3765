// The whole MC in lockstep: high-level commands through the state machine make the simulated
// robot stand and walk (the path a real client's commands take, without the transport).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "app/lockstep_client.hpp"
#include "app/simulated_robot.hpp"

namespace cerebellum {
namespace {

HighLevelCommand command(ModeId mode, int gait, double vx = 0.0, double yaw_rate = 0.0) {
  return high_level_command(mode, gait, vx, 0.0, yaw_rate);
}

McConfig lying_start() {
  McConfig config = default_config();
  config.startup = Startup::Off;
  return config;
}

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
