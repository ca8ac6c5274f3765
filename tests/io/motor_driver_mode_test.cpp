// The drivers' mode as the firmware reports it (motor_error bits 30..31 of robot_control_response
// and spi_data; joint_state_t.flags bit 0 of the shared memory): reset while the MC drives nothing
// (Off, as after power-on; the motors stopped by a protection), motor mode while it runs a command.
// The whole MC in lockstep on the simulated robot, each field through its encoder.
#include <gtest/gtest.h>

#include <cstdint>

#include "backend/motor_model.hpp"
#include "core/robot_model.hpp"
#include "io/common/motor_error_word.hpp"
#include "io/lcm_highlevel/highlevel_wire.hpp"
#include "io/lcm_motor_sdk/motor_sdk_wire.hpp"
#include "io/shm_lowlevel/shm_codec.hpp"
#include "loop/lockstep_client.hpp"
#include "loop/simulated_robot.hpp"
#include "lowlevel/lowlevel.h"

namespace cerebellum {
namespace {

struct Fields {
  std::uint32_t response_mode_bits = 0;  // the same for all 12 motors, else 99
  std::uint32_t spi_mode_bits = 0;
  bool shm_enabled = false;  // bit 0 of every joint_state_t.flags
};

Fields fields_of(const CycleRecord& record) {
  const robot_control_response_lcmt response = make_response(record.high_level.status);
  const spi_data_t spi = make_spi_data(record.state);
  Fields f;
  f.response_mode_bits = static_cast<std::uint32_t>(response.motor_error[0]) >> 30;
  f.spi_mode_bits = static_cast<std::uint32_t>(spi.flags[0]) >> 30;
  f.shm_enabled = true;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    if ((static_cast<std::uint32_t>(response.motor_error[i]) >> 30) != f.response_mode_bits) f.response_mode_bits = 99;
    if ((static_cast<std::uint32_t>(spi.flags[i]) >> 30) != f.spi_mode_bits) f.spi_mode_bits = 99;
    const std::int32_t flags = shm_joint_state_flags(record.state.temperature_c[i], record.state.motor_faults[i], 24.0,
                                                     record.state.driver_mode[i]);
    if ((flags & JOINT_STATE_ENABLED) == 0) f.shm_enabled = false;
  }
  return f;
}

TEST(MotorDriverMode, ReadsResetWhileTheRobotLiesOffAndMotorModeOnceTheMcDrivesIt) {
  Mc mc = make_simulated_mc(default_config());  // starts in Off, as the robot after power-on
  LockstepClient client(mc);
  CycleRecord last;
  const auto keep = [&](const CycleRecord& record) { last = record; };
  client.run(high_level_command(ModeId::Off, 0), 1.0, keep);
  Fields f = fields_of(last);
  EXPECT_EQ(f.response_mode_bits, 0u) << "reset";
  EXPECT_EQ(f.spi_mode_bits, 0u);
  EXPECT_FALSE(f.shm_enabled);

  client.run(high_level_command(ModeId::RecoveryStand, 0), 3.0, keep);
  f = fields_of(last);
  EXPECT_EQ(f.response_mode_bits, 2u) << "motor mode";
  EXPECT_EQ(f.spi_mode_bits, 2u);
  EXPECT_TRUE(f.shm_enabled);
  EXPECT_EQ(static_cast<std::uint32_t>(make_response(last.high_level.status).motor_error[0]), kMotorErrorWordHealthy);

  // damping drives the motors (kd): still motor mode; Off again: reset
  client.run(high_level_command(ModeId::PureDamper, 0), 1.0, keep);
  EXPECT_EQ(fields_of(last).response_mode_bits, 2u);
  client.run(high_level_command(ModeId::Off, 0), 0.5, keep);
  EXPECT_EQ(fields_of(last).response_mode_bits, 0u);
}

TEST(MotorDriverMode, AMotorTurnedFasterThanItsNoLoadSpeedReadsOverSpeedInTheSharedMemory) {
  SensorFrame frame;
  frame.qd[4] = 1.2 * robot::kNoLoadSpeedRadS;
  EXPECT_EQ(motor_over_speed(frame.qd[4]), kMotorOverSpeed);
  EXPECT_EQ(motor_over_speed(0.9 * robot::kNoLoadSpeedRadS), kMotorOk);
  EXPECT_EQ(motor_over_speed(-1.2 * robot::kNoLoadSpeedRadS), kMotorOverSpeed);
  EXPECT_NE(shm_joint_state_flags(30.0, kMotorOverSpeed, 24.0) & JOINT_STATE_OVER_SPEED, 0);
  EXPECT_EQ(shm_joint_state_flags(30.0, kMotorOk, 24.0) & JOINT_STATE_OVER_SPEED, 0);
  // not an error: the driver keeps running, the CyberDog2 word has no bit for it
  EXPECT_EQ(motor_error_word(kMotorOverSpeed, MotorDriverMode::Motor), kMotorErrorWordHealthy);
}

}  // namespace
}  // namespace cerebellum
