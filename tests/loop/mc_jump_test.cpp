// Jumps (mode 16) and force jumps (mode 22) through the whole MC in lockstep, judged on the
// simulation's ground truth: each jump id from a stand reaches its target (or the documented
// figure where the 12 Nm body falls short, docs/jumps.md), lands without a fall and stands again;
// the response follows the jump; jumps the state forbids are refused; a landing that goes wrong
// ends in damping and the usual recovery stand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "loop/lockstep_client.hpp"
#include "loop/simulated_robot.hpp"
#include "backend/sim_fixture.hpp"
#include "modes/jump_mode.hpp"

namespace cerebellum {
namespace {

McConfig lying_start(const std::string& model = "") {
  McConfig config = default_config();
  config.startup = Startup::Off;
  if (!model.empty()) {
    config.robot.model_path = std::string(CEREBELLUM_MODEL_DIR) + "/" + model;
    config.robot.initial_height_m = 0.4;  // on the 10 cm landing
  }
  return config;
}

double degrees(double rad) { return rad * 180.0 / robot::kPi; }

// what one jump did, on the truth
struct JumpOutcome {
  Eigen::Vector2d displacement_m = Eigen::Vector2d::Zero();  // heading frame at the start
  double turn_rad = 0.0;
  double rise_m = 0.0;        // highest trunk above its start
  double final_drop_m = 0.0;  // trunk height at the start minus at the end
  double largest_tilt_rad = 0.0;
  bool reported_the_jump = false;  // the response showed the mode and jump id while it ran
  bool progress_never_fell = true;
  bool ever_lifted = false;
  HighLevelStatus final_status;
  double final_tilt_rad = 0.0;
  // in the air (no foot on the ground): the worst horizontal disagreement of the MC's velocity
  // estimate with the truth
  double worst_flight_velocity_error_m_s = 0.0;
  double slowest_flight_estimate_m_s = 1e9;  // forward (world x; the robot starts facing +x)
};

struct JumpRun {
  explicit JumpRun(const std::string& model = "") : mc(make_simulated_mc(lying_start(model))), client(mc) {
    client.run(high_level_command(ModeId::RecoveryStand, 0), 3.0);
    client.run(high_level_command(ModeId::Locomotion, 1), 1.0);
  }

  GroundTruth truth() { return mc.simulation().ground_truth(); }

  JumpOutcome jump(const HighLevelCommand& command, double seconds = 4.0) {
    const GroundTruth before = truth();
    const double yaw0 = testing::truth_rpy(before).z();
    JumpOutcome outcome;
    int last_bar = 0;
    client.run(command, seconds, [&](const CycleRecord& record) {
      const GroundTruth g = truth();
      const Eigen::Vector3d rpy = testing::truth_rpy(g);
      if (std::none_of(g.foot_contact.begin(), g.foot_contact.end(), [](bool c) { return c; })) {
        const double error = std::hypot(record.state.velocity_world.x() - g.velocity_world[0],
                                        record.state.velocity_world.y() - g.velocity_world[1]);
        outcome.worst_flight_velocity_error_m_s = std::max(outcome.worst_flight_velocity_error_m_s, error);
        outcome.slowest_flight_estimate_m_s =
            std::min(outcome.slowest_flight_estimate_m_s, record.state.velocity_world.x());
      }
      outcome.rise_m = std::max(outcome.rise_m, g.position[2] - before.position[2]);
      outcome.largest_tilt_rad = std::max({outcome.largest_tilt_rad, std::abs(rpy.x()), std::abs(rpy.y())});
      const HighLevelStatus& s = mc.machine().status();
      outcome.ever_lifted |= s.mode == static_cast<int>(ModeId::Lifted);
      if (s.mode == command.mode && s.gait_id == command.gait_id) {
        outcome.reported_the_jump = true;
        outcome.progress_never_fell &= s.order_process_bar >= last_bar;
        last_bar = s.order_process_bar;
      }
    });
    const GroundTruth after = truth();
    const Eigen::Vector2d moved(after.position[0] - before.position[0], after.position[1] - before.position[1]);
    outcome.displacement_m = Eigen::Rotation2Dd(-yaw0) * moved;
    outcome.turn_rad = std::remainder(testing::truth_rpy(after).z() - yaw0, 2.0 * robot::kPi);
    outcome.final_drop_m = before.position[2] - after.position[2];
    outcome.final_status = mc.machine().status();
    const Eigen::Vector3d rpy = testing::truth_rpy(after);
    outcome.final_tilt_rad = std::max(std::abs(rpy.x()), std::abs(rpy.y()));
    return outcome;
  }

  Mc mc;
  LockstepClient client;
};

// landed on its feet and standing in the mode that jumped, the jump reported all along
void expect_landed_and_standing(const JumpOutcome& jump, int mode, int gait) {
  EXPECT_LT(jump.largest_tilt_rad, 0.6);
  EXPECT_TRUE(jump.reported_the_jump);
  EXPECT_TRUE(jump.progress_never_fell);
  EXPECT_FALSE(jump.ever_lifted) << "a jump is not a lift";
  EXPECT_EQ(jump.final_status.mode, mode);
  EXPECT_EQ(jump.final_status.gait_id, gait);
  EXPECT_EQ(jump.final_status.order_process_bar, 100);
  EXPECT_EQ(jump.final_status.switch_status, SwitchStatus::Done);
  EXPECT_LT(jump.final_tilt_rad, 0.05);
}

HighLevelCommand jump_command(int gait) { return high_level_command(ModeId::Jump3d, gait); }

TEST(McJumps, JumpForwardThirtyCentimetresLandsWithinFifteenPercentAndStands) {
  JumpRun run;
  const JumpOutcome jump = run.jump(jump_command(4));
  expect_landed_and_standing(jump, 16, 4);
  EXPECT_NEAR(jump.displacement_m.x(), 0.3, 0.15 * 0.3);
  EXPECT_NEAR(jump.displacement_m.y(), 0.0, 0.05);
  EXPECT_NEAR(jump.final_drop_m, 0.0, 0.02);
}

TEST(McJumps, JumpForwardSixtyCentimetresLandsWithinFifteenPercentAndStands) {
  // the push leaves slower than planned (the motors' torque falls with speed): the feet, placed
  // in the air from the take-off the push was on course for, reach out for the rest
  JumpRun run;
  const JumpOutcome jump = run.jump(jump_command(1));
  expect_landed_and_standing(jump, 16, 1);
  EXPECT_NEAR(jump.displacement_m.x(), 0.6, 0.15 * 0.6);
  EXPECT_NEAR(jump.displacement_m.y(), 0.0, 0.05);
}

TEST(McJumps, InTheAirTheVelocityEstimateNoLongerTakesTheSwingingLegsForStanceFeet) {
  // the legs swinging to their landing pose load their joints as if the feet pushed: read as
  // contacts, their odometry turned the estimate backward (-1.05 m/s for a true +0.98; worst
  // error 2.3 m/s). With no foot planned on the ground the estimate keeps its direction; the
  // untrusted legs still pull it down to about 0.2 m/s by touchdown (docs/estimation.md)
  JumpRun run;
  const JumpOutcome jump = run.jump(jump_command(1));
  expect_landed_and_standing(jump, 16, 1);
  EXPECT_GT(jump.slowest_flight_estimate_m_s, 0.0);
  EXPECT_LT(jump.worst_flight_velocity_error_m_s, 1.0);
}

TEST(McJumps, JumpsLeftAndRightTwentyCentimetresLandWithinFiveCentimetres) {
  for (const auto& [gait, left] : {std::pair{2, 0.2}, std::pair{5, -0.2}}) {
    JumpRun run;
    const JumpOutcome jump = run.jump(jump_command(gait));
    expect_landed_and_standing(jump, 16, gait);
    EXPECT_NEAR(jump.displacement_m.y(), left, 0.05) << "jump " << gait;
    EXPECT_NEAR(jump.displacement_m.x(), 0.0, 0.05) << "jump " << gait;
  }
}

TEST(McJumps, TurningJumpsTurnNinetyDegreesWithinTenAndLandInPlace) {
  for (const auto& [gait, turn_deg] : {std::pair{0, 90.0}, std::pair{3, -90.0}}) {
    JumpRun run;
    const JumpOutcome jump = run.jump(jump_command(gait));
    expect_landed_and_standing(jump, 16, gait);
    EXPECT_NEAR(degrees(jump.turn_rad), turn_deg, 10.0) << "jump " << gait;
    EXPECT_LT(jump.displacement_m.norm(), 0.06) << "jump " << gait;
  }
}

TEST(McJumps, TheUpJumpRaisesTheTrunkThirtyCentimetresWithinFifteenPercentAndLandsInPlace) {
  JumpRun run;
  const JumpOutcome jump = run.jump(jump_command(6));
  expect_landed_and_standing(jump, 16, 6);
  EXPECT_GT(jump.rise_m, 0.3 * 0.85);
  EXPECT_LT(jump.displacement_m.norm(), 0.1);
}

TEST(McJumps, JumpDownAStairLeavesTheLandingAndStandsOnTheFloorBelow) {
  JumpRun run("terrain_stair_down10cm.xml");
  const JumpOutcome jump = run.jump(jump_command(9));
  expect_landed_and_standing(jump, 16, 9);
  // every foot on the floor 10 cm below, clear of the landing's edge (0.22 m ahead of the start)
  EXPECT_NEAR(jump.final_drop_m, 0.1, 0.02);
  const GroundTruth g = run.truth();
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) EXPECT_TRUE(g.foot_contact[leg]);
  EXPECT_GT(jump.displacement_m.x(), 0.4);
}

TEST(McJumps, AForceJumpTakesOffWithTheAskedAccelerationLandsAndStands) {
  JumpRun run;
  // mode 22 may follow a recovery stand (the reference's transitions)
  run.client.run(high_level_command(ModeId::RecoveryStand, 0), 0.5);
  HighLevelCommand in_place = high_level_command(ModeId::ForceJump, 0);
  in_place.acc_des = {0.0f, 0.0f, 12.0f, 0.0f, 0.0f, 0.0f};
  const JumpOutcome hop = run.jump(in_place);
  expect_landed_and_standing(hop, 22, 0);
  EXPECT_LT(hop.displacement_m.norm(), 0.06);
  EXPECT_GT(hop.rise_m, 0.05);

  JumpRun forward_run;
  forward_run.client.run(high_level_command(ModeId::RecoveryStand, 0), 0.5);
  HighLevelCommand forward = in_place;
  forward.acc_des = {4.0f, 0.0f, 12.0f, 0.0f, 0.0f, 0.0f};
  const JumpOutcome leap = forward_run.jump(forward);
  expect_landed_and_standing(leap, 22, 0);
  EXPECT_GT(leap.displacement_m.x(), 0.15);
  EXPECT_GT(leap.displacement_m.x(), hop.displacement_m.x() + 0.1);
}

TEST(McJumps, AJumpWhileTrottingAtOneMetrePerSecondIsRefusedWithTheReason) {
  JumpRun run;
  run.client.run(high_level_command(ModeId::Locomotion, 3, 1.0), 3.0);
  while (run.mc.machine().refusals().try_pop()) {
  }
  run.client.run(jump_command(4), 0.3);
  EXPECT_EQ(run.mc.machine().status().mode, 11);
  EXPECT_EQ(run.mc.machine().status().switch_status, SwitchStatus::BanTransition);
  bool refused_for_speed = false;
  while (const auto note = run.mc.machine().refusals().try_pop()) {
    refused_for_speed |= note->mode == 16 && std::string(note->reason).find("faster") != std::string::npos;
  }
  EXPECT_TRUE(refused_for_speed);
  // still trotting: the refusal changed nothing
  EXPECT_GT(run.truth().velocity_world[0], 0.6);
}

TEST(McJumps, AFlipIsRefusedForLowBatteryBelowItsOwnThreshold) {
  JumpRun run;
  ASSERT_EQ(run.mc.faults()->request(parse_fault("battery soc 35").request.value()), "");
  run.client.run(high_level_command(ModeId::Locomotion, 1), 0.5);
  run.client.run(jump_command(kFrontFlipGaitId), 0.3);
  EXPECT_EQ(run.mc.machine().status().switch_status, SwitchStatus::LowBattery);
  // a back flip needs only 20 %
  ASSERT_EQ(run.mc.faults()->request(parse_fault("battery soc 15").request.value()), "");
  run.client.run(high_level_command(ModeId::Locomotion, 1), 0.5);
  run.client.run(jump_command(kBackFlipGaitId), 0.3);
  EXPECT_EQ(run.mc.machine().status().switch_status, SwitchStatus::LowBattery);
  EXPECT_EQ(run.mc.machine().status().mode, 11);
  EXPECT_GT(run.truth().position[2], 0.2);
}

TEST(McJumps, AClientThatVanishesMidJumpHasTheRobotLandBeforeItIsDamped) {
  JumpRun run;
  // the command, a heartbeat or two, then silence from the crouch on
  run.client.run(jump_command(4), 0.15);
  bool damped_before_landing = false;
  bool damped = false;
  double largest_tilt = 0.0;
  for (int tick = 0; tick < 1500; ++tick) {
    run.mc.loop().tick();
    const HighLevelStatus& s = run.mc.machine().status();
    if (s.mode == static_cast<int>(ModeId::PureDamper) && !damped) {
      damped = true;
      damped_before_landing = !run.mc.modes().jump().controller().finished();
    }
    const Eigen::Vector3d rpy = testing::truth_rpy(run.truth());
    largest_tilt = std::max({largest_tilt, std::abs(rpy.x()), std::abs(rpy.y())});
  }
  // the timeout's protection still comes, once the jump stands on its feet
  EXPECT_TRUE(damped);
  EXPECT_FALSE(damped_before_landing);
  EXPECT_LT(largest_tilt, 0.6);
  EXPECT_EQ(run.mc.machine().counters(HighLevelSource::CyberDog2Lcm).timeouts.load(), 1u);
}

TEST(McJumps, AFlipIsRefusedWithOverHeatWhileAMotorReadsAboveSeventyFourDegrees) {
  JumpRun run;
  // warm, below the driver's 82 deg C warning: the robot stands on, only a flip is refused
  ASSERT_EQ(run.mc.faults()->request(parse_fault("motor RL_knee hot 78").request.value()), "");
  run.client.run(high_level_command(ModeId::Locomotion, 1), 0.5);
  run.client.run(jump_command(kBackFlipGaitId), 0.3);
  EXPECT_EQ(run.mc.machine().status().switch_status, SwitchStatus::OverHeat);
  EXPECT_EQ(run.mc.machine().status().mode, 11);
  // an ordinary jump is still allowed at that temperature
  run.client.run(high_level_command(ModeId::Locomotion, 1), 0.5);
  const JumpOutcome jump = run.jump(jump_command(4), 3.0);
  expect_landed_and_standing(jump, 16, 4);
  // hotter than the warning: the driver's warning bit, and the reference's high damping
  ASSERT_EQ(run.mc.faults()->request(parse_fault("motor RL_knee hot 84").request.value()), "");
  run.client.run(high_level_command(ModeId::Locomotion, 1), 0.3);
  EXPECT_EQ(run.mc.machine().status().switch_status, SwitchStatus::HighDamping);
  EXPECT_NE(run.mc.machine().status().motor_faults[11] & kMotorTemperatureWarning, 0u);
}

TEST(McJumps, ALandingKnockedOverInTheAirEndsInDampingAndTheRecoveryStandRightsTheRobot) {
  JumpRun run;
  // a hard shove sideways just after take-off (about 0.7 s into the jump)
  run.client.run(jump_command(4), 0.68);
  run.mc.simulation().request_force_pulse(ForcePulse{{0.0, 400.0, 0.0}, 0.08});
  bool damped = false;
  run.client.run(jump_command(4), 3.0, [&](const CycleRecord&) {
    const HighLevelStatus& s = run.mc.machine().status();
    damped |= s.switch_status == SwitchStatus::HighDamping || s.switch_status == SwitchStatus::EmergencyStop;
  });
  EXPECT_TRUE(damped);
  run.client.run(high_level_command(ModeId::RecoveryStand, 0), 8.0);
  EXPECT_EQ(run.mc.machine().status().mode, 12);
  EXPECT_EQ(run.mc.machine().status().order_process_bar, 100);
  EXPECT_GT(run.truth().position[2], 0.2);
  EXPECT_LT(std::abs(testing::truth_rpy(run.truth()).x()), 0.1);
}

}  // namespace
}  // namespace cerebellum
