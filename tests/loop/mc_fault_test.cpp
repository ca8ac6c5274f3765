// Faults injected into the simulated robot and answered by the whole MC as the reference
// describes (cyberdog2-highlevel.md section 5): high damping, the motors off after 3 s, commands
// ignored until the cause clears, and a stand again on request. Lockstep, judged on the truth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "loop/lockstep_client.hpp"
#include "loop/simulated_robot.hpp"
#include "backend/sim_fixture.hpp"

namespace cerebellum {
namespace {

McConfig standing_start() {
  McConfig config = default_config();
  config.startup = Startup::Off;
  return config;
}

FaultRequest fault(const std::string& text) {
  const FaultParse parsed = parse_fault(text);
  EXPECT_TRUE(parsed.request.has_value()) << parsed.error;
  return parsed.request.value_or(FaultRequest{});
}

struct Sample {
  double time_s;
  SwitchStatus status;
  int mode;
  double max_tilt_rad;
};

// the robot up and trotting in place, ready for a fault
struct FaultRun {
  FaultRun() : mc(make_simulated_mc(standing_start())), client(mc) {
    client.run(high_level_command(ModeId::RecoveryStand, 0), 3.0);
  }
  void inject(const std::string& text) { ASSERT_EQ(mc.faults()->request(fault(text)), ""); }
  double height() { return mc.simulation().ground_truth().position[2]; }
  double tilt() {
    const Eigen::Vector3d rpy = testing::truth_rpy(mc.simulation().ground_truth());
    return std::max(std::abs(rpy.x()), std::abs(rpy.y()));
  }
  // keeps sending the command for seconds; the first time each switch_status was seen, and the
  // largest tilt on the way
  void run(const HighLevelCommand& command, double seconds) {
    client.run(command, seconds, [&](const CycleRecord&) {
      const HighLevelStatus& s = mc.machine().status();
      max_tilt_rad = std::max(max_tilt_rad, tilt());
      if (first_seen_s[static_cast<int>(s.switch_status)] < 0.0) {
        first_seen_s[static_cast<int>(s.switch_status)] = mc.backend().time_s();
      }
    });
  }
  void forget_statuses() { std::fill(std::begin(first_seen_s), std::end(first_seen_s), -1.0); }
  double seen(SwitchStatus status) const { return first_seen_s[static_cast<int>(status)]; }

  Mc mc;
  LockstepClient client;
  double first_seen_s[8] = {-1, -1, -1, -1, -1, -1, -1, -1};
  double max_tilt_rad = 0.0;
};

TEST(McFaults, ADisconnectedMotorWhileTrottingDampsLiesDownStopsAfterThreeSecondsAndStandsAgainOnceCleared) {
  FaultRun run;
  const HighLevelCommand trot = high_level_command(ModeId::Locomotion, 3, 0.3);
  run.run(trot, 2.0);
  ASSERT_GT(run.height(), 0.2);
  run.forget_statuses();
  run.inject("motor FR_knee disconnected");
  const double injected_s = run.mc.backend().time_s();
  // the client keeps asking to trot: ignored while the fault lasts
  run.run(trot, 0.2);
  // a new command is refused with the reason
  run.run(high_level_command(ModeId::Locomotion, 3, 0.4), 0.1);
  bool refused_for_the_motor = false;
  while (const auto note = run.mc.machine().refusals().try_pop()) {
    refused_for_the_motor |=
        std::string(note->reason) == "motor error or warning: commands are ignored until it clears";
  }
  EXPECT_TRUE(refused_for_the_motor);
  run.run(trot, 4.7);
  EXPECT_NEAR(run.seen(SwitchStatus::HighDamping) - injected_s, 0.0, 0.01);
  EXPECT_NEAR(run.seen(SwitchStatus::EmergencyStop) - injected_s, 3.0, 0.01);
  EXPECT_EQ(run.mc.machine().status().switch_status, SwitchStatus::EmergencyStop);
  EXPECT_EQ(run.mc.machine().status().motor_faults[2], kMotorDisconnected);
  EXPECT_EQ(run.mc.machine().status().motor_faults[0], kMotorOk);
  // lay down without a fall: on its belly, never tipped
  EXPECT_LT(run.height(), 0.15);
  EXPECT_LT(run.max_tilt_rad, 0.6);  // no fall: the benchmarks' 34 degrees
  // the motors are off: the guard wrote the passive command
  const JointCommand& written = run.mc.loop().last_cycle().command;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    EXPECT_EQ(written.kp[i], 0.0);
    EXPECT_EQ(written.kd[i], 0.0);
    EXPECT_EQ(written.tau_ff[i], 0.0);
  }
  // the fault clears: the protection ends 0.5 s later, and a stand sent then is obeyed
  run.inject("clear");
  run.run(high_level_command(ModeId::PureDamper, 0), 0.6);
  EXPECT_EQ(run.mc.machine().status().mode, 0);  // Off: the motors were stopped
  run.run(high_level_command(ModeId::RecoveryStand, 0), 4.0);
  EXPECT_EQ(run.mc.machine().status().switch_status, SwitchStatus::Done);
  EXPECT_EQ(run.mc.machine().status().mode, 12);
  EXPECT_GT(run.height(), 0.2);
}

TEST(McFaults, AnOverheatedMotorReportsTheWarningAndTheErrorAndProtects) {
  FaultRun run;
  run.inject("motor 4 over_temperature for 1");
  run.run(high_level_command(ModeId::RecoveryStand, 0), 0.1);
  EXPECT_EQ(run.mc.machine().status().motor_faults[4], kMotorOverTemperature | kMotorTemperatureWarning);
  EXPECT_EQ(run.mc.machine().status().switch_status, SwitchStatus::HighDamping);
  // the fault ends by itself after 1 s, the protection 0.5 s later: before the motors go off
  run.run(high_level_command(ModeId::RecoveryStand, 0), 1.5);
  EXPECT_LT(run.seen(SwitchStatus::EmergencyStop), 0.0);
  EXPECT_EQ(run.mc.machine().status().motor_faults[4], kMotorOk);
  EXPECT_EQ(run.mc.machine().status().mode, 7);
  run.run(high_level_command(ModeId::RecoveryStand, 0), 4.0);
  EXPECT_EQ(run.mc.machine().status().switch_status, SwitchStatus::Done);
  EXPECT_GT(run.height(), 0.2);
}

TEST(McFaults, ABatteryAtItsCriticalLevelLaysTheRobotDownUntilItIsCharged) {
  FaultRun run;
  run.inject("battery soc 4");
  run.run(high_level_command(ModeId::QpStand, 0), 2.0);
  EXPECT_EQ(run.mc.machine().status().switch_status, SwitchStatus::HighDamping);
  EXPECT_EQ(run.mc.loop().last_cycle().health.causes, kHealthBatteryCritical);
  EXPECT_LT(run.height(), 0.15);
  // a charged battery (the fault cleared): once the protection has ended, a stand is obeyed
  run.inject("clear battery");
  run.run(high_level_command(ModeId::PureDamper, 0), 0.6);
  run.run(high_level_command(ModeId::RecoveryStand, 0), 4.0);
  EXPECT_EQ(run.mc.machine().status().switch_status, SwitchStatus::Done);
  EXPECT_GT(run.height(), 0.2);
}

TEST(McFaults, AStuckImuOnAWalkingRobotIsDetectedAndTheRobotLiesDown) {
  FaultRun run;
  const HighLevelCommand trot = high_level_command(ModeId::Locomotion, 3, 0.0);
  run.run(trot, 1.0);
  run.inject("imu stuck");
  const double injected_s = run.mc.backend().time_s();
  run.forget_statuses();
  run.run(trot, 2.0);
  EXPECT_GT(run.seen(SwitchStatus::HighDamping), injected_s);
  EXPECT_LT(run.seen(SwitchStatus::HighDamping) - injected_s, 0.2);
  EXPECT_TRUE(run.mc.loop().last_cycle().health.causes & kHealthImuStuck);
  EXPECT_LT(run.height(), 0.15);
  EXPECT_LT(run.max_tilt_rad, 0.6);  // no fall: the benchmarks' 34 degrees
}

TEST(McFaults, AnImuThatSendsNaNIsNeverTurnedIntoACommand) {
  FaultRun run;
  run.inject("imu nan");
  run.run(high_level_command(ModeId::RecoveryStand, 0), 4.0);
  EXPECT_TRUE(run.mc.loop().last_cycle().health.causes & kHealthStateInvalid);
  EXPECT_EQ(run.mc.loop().last_cycle().health.protection, Protection::Stopped);
  EXPECT_LT(run.height(), 0.15);
  EXPECT_LT(run.max_tilt_rad, 0.6);  // no fall: the benchmarks' 34 degrees
}

TEST(McFaults, AProtectionWhileTheStateCannotBeTrustedIsReportedAndStopsTheRunningMode) {
  // the NaN lasts 0.5 s: the controller is not asked while it lasts, yet the response says EDAMP
  // and, once the IMU is back, the stand the client still heartbeats does not resume by itself
  FaultRun run;
  HighLevelCommand stand = high_level_command(ModeId::RecoveryStand, 0);
  stand.life_count = 100;
  const auto heartbeat = [&](double seconds) {
    for (int tick = 0; tick < static_cast<int>(seconds / 0.002 + 0.5); ++tick) {
      if (tick % 50 == 0) run.mc.machine().submit(stand, run.mc.backend().time_s());
      run.max_tilt_rad = std::max(run.max_tilt_rad, run.tilt());
      run.mc.loop().tick();
    }
  };
  heartbeat(0.5);
  ASSERT_EQ(run.mc.machine().status().mode, 12);
  run.inject("imu nan for 0.5");
  heartbeat(0.3);
  EXPECT_EQ(run.mc.machine().status().switch_status, SwitchStatus::HighDamping);
  heartbeat(2.0);
  EXPECT_EQ(run.mc.machine().status().mode, 7);
  EXPECT_EQ(run.mc.machine().status().switch_status, SwitchStatus::Done);
  EXPECT_LT(run.height(), 0.15);
  EXPECT_LT(run.max_tilt_rad, 0.6);
}

}  // namespace
}  // namespace cerebellum
