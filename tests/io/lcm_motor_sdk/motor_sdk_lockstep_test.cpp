// The motor SDK in the whole MC, in lockstep on the simulated robot: a client written like the
// official example activates motor mode, lays the legs out and stands the robot up; a client that
// dies makes the robot lie down, and only all-zero frames bring the interface back.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "loop/mc.hpp"
#include "loop/simulated_robot.hpp"
#include "core/robot_model.hpp"
#include "io/common/motor_error_word.hpp"
#include "io/lcm_highlevel/highlevel_wire.hpp"
#include "io/lcm_motor_sdk/motor_sdk_wire.hpp"
#include "io/shm_lowlevel/shm_codec.hpp"
#include "lowlevel/lowlevel.h"
#include "lowlevel/motor_sdk/motor_sdk_source.hpp"

namespace cerebellum {
namespace {

// a user program: the frame it sends after seeing the feedback and err_flag
class SdkClient {
 public:
  virtual ~SdkClient() = default;
  virtual JointCommand next(const RobotState& feedback, std::uint16_t err_flag) = 0;
};

// the official example's logic in SDK convention: all-zero while err_flag bit1 is set, then from
// the current pose to lying over 1500 ticks, to standing over 1500 ticks, kp 60, kd 2
class ExampleClient final : public SdkClient {
 public:
  JointCommand next(const RobotState& feedback, std::uint16_t err_flag) override {
    JointCommand frame;
    if (err_flag & kMotorSdkCommandLost) {
      start_q_ = feedback.q;
      tick_ = 0;
      return frame;
    }
    const double t = std::min(2.0, tick_++ / 1500.0);
    for (std::size_t i = 0; i < kNumJoints; ++i) {
      const double lying = robot::kLyingPose[i % 3], standing = robot::kStandPose[i % 3];
      frame.q_des[i] = t < 1.0 ? start_q_[i] * (1.0 - t) + lying * t : lying * (2.0 - t) + standing * (t - 1.0);
      frame.kp[i] = 60.0;
      frame.kd[i] = 2.0;
    }
    return frame;
  }

 private:
  JointArray<double> start_q_{};
  long tick_ = 0;
};

// the mistake of issue 13: activation, then the standing pose in one frame (kp 60, kd 2)
class JumpToStandClient final : public SdkClient {
 public:
  JointCommand next(const RobotState&, std::uint16_t err_flag) override {
    JointCommand frame;
    if (err_flag & kMotorSdkCommandLost) return frame;
    for (std::size_t i = 0; i < kNumJoints; ++i) {
      frame.q_des[i] = robot::kStandPose[i % 3];
      frame.kp[i] = 60.0;
      frame.kd[i] = 2.0;
    }
    return frame;
  }
};

class MotorSdkLockstep : public ::testing::Test {
 protected:
  MotorSdkLockstep() : mc_(make_simulated_mc(damper_config())), source_(MotorSdkParameters{}) {
    mc_.arbiter().add_low_level_source(source_);
  }

  static McConfig damper_config() {
    McConfig config = default_config();
    config.startup = Startup::Damper;
    return config;
  }

  // one tick; the client's frame (if any) arrives stamped with the robot time of the last record
  void tick(SdkClient* client) {
    const RobotState& feedback = mc_.loop().last_cycle().state;
    if (client != nullptr) {
      ASSERT_EQ(source_.mailbox().push(client->next(feedback, source_.status().err_flag), feedback.time_s),
                PushResult::Accepted);
    }
    mc_.loop().tick();
  }
  void run(double seconds, SdkClient* client) {
    const int ticks = static_cast<int>(seconds / mc_.loop().period_s() + 0.5);
    for (int k = 0; k < ticks; ++k) tick(client);
  }
  double height_m() { return mc_.simulation().ground_truth().position[2]; }
  // z of the trunk's up axis in the world: 1 upright, below 0 on its back
  double up_z() {
    const std::array<double, 4> q = mc_.simulation().ground_truth().quat;
    return 1.0 - 2.0 * (q[1] * q[1] + q[2] * q[2]);
  }
  std::uint16_t err_flag() const { return source_.status().err_flag; }

  Mc mc_;
  MotorSdkSource source_;
};

TEST_F(MotorSdkLockstep, ExampleClientStandsTheRobotUpAndADeadClientLetsItLieDown) {
  // the robot drops, settles in PureDamper; nothing latched yet
  run(0.5, nullptr);
  EXPECT_EQ(mc_.arbiter().latched(), nullptr);

  ExampleClient client;
  run(1.0, &client);
  EXPECT_EQ(mc_.arbiter().latched(), &source_);
  EXPECT_EQ(err_flag(), kMotorSdkCommandLost);  // still activating: bit1 holds for 2 s
  run(1.1, &client);
  EXPECT_EQ(err_flag(), 0);
  const double lying_height_m = height_m();
  EXPECT_LT(lying_height_m, 0.17);

  // 3 s to the lying pose, 3 s up, 1 s of holding
  run(7.0, &client);
  EXPECT_EQ(err_flag(), 0);
  EXPECT_GE(height_m(), 0.2);
  EXPECT_EQ(source_.counters().clamped_jumps, 0u);

  // the client dies: bit1 after 500 ms, damping, the robot is down within 3 s
  run(0.6, nullptr);
  EXPECT_EQ(err_flag() & kMotorSdkCommandLost, kMotorSdkCommandLost);
  run(3.0, nullptr);
  EXPECT_LT(height_m(), 0.17);
  EXPECT_EQ(source_.counters().commands_lost, 1u);

  // a new client: zero frames clear bit1 (it has been set for more than 2 s), then it stands again
  ExampleClient second;
  run(0.1, &second);
  EXPECT_EQ(err_flag(), 0);
  run(7.0, &second);
  EXPECT_EQ(err_flag(), 0);
  EXPECT_GE(height_m(), 0.2);
}

TEST_F(MotorSdkLockstep, JumpFromLyingToStandingInOneFrameIsSlowedToASafeStandUp) {
  run(0.5, nullptr);
  JumpToStandClient client;
  // all-zero frames until bit1 clears (2 s after entering motor mode)
  for (int k = 0; k < 1500 && source_.status().err_flag != 0; ++k) tick(&client);
  ASSERT_EQ(err_flag(), 0);
  EXPECT_LT(height_m(), 0.17);

  // the standing pose at once: the firmware's rule lets each joint's target lead the measured
  // angle by at most 8 / 10 / 12 deg, so the robot rises without leaving the ground
  double highest_m = 0.0, lowest_up_z = 1.0;
  for (int k = 0; k < 2000; ++k) {
    tick(&client);
    highest_m = std::max(highest_m, height_m());
    lowest_up_z = std::min(lowest_up_z, up_z());
  }
  EXPECT_GT(source_.counters().clamped_jumps, 0u);
  EXPECT_LT(highest_m, 0.32) << "the trunk was thrown up";
  EXPECT_GT(lowest_up_z, 0.9) << "the trunk tipped over";
  EXPECT_GE(height_m(), 0.2) << "the robot did not stand up";
  EXPECT_EQ(err_flag(), 0) << "the target has been reached: no jump clamped any more";
}

TEST_F(MotorSdkLockstep, AMotorFaultInMotorModeDampsWhateverTheClientSendsAndReportsTheMotor) {
  // seed section 4: battery and motor-fault protections still work under the motor SDK
  run(0.5, nullptr);
  ExampleClient client;
  run(9.0, &client);
  ASSERT_GE(height_m(), 0.2);
  ASSERT_EQ(mc_.faults()->request(parse_fault("motor RL_knee driver_fault").request.value()), "");
  run(0.1, &client);
  // the client sees the motor's bit in spi_data (the seed's example stops on it)
  const spi_data_t spi = make_spi_data(mc_.loop().last_cycle().state);
  // the faulted driver has stopped its motor: reset (bits 30..31 = 0) with its error bit
  EXPECT_EQ(static_cast<std::uint32_t>(spi.flags[11]), 0x00000004u);
  EXPECT_EQ(static_cast<std::uint32_t>(spi.flags[10]), 0x80000000u);
  // its stiff commands are replaced by damping: the robot sinks; after 3 s the motors are off
  EXPECT_EQ(mc_.loop().last_cycle().safety.flags, kGuardHealthDamping);
  run(3.0, &client);
  EXPECT_EQ(mc_.loop().last_cycle().safety.flags, kGuardHealthStopped);
  EXPECT_LT(height_m(), 0.17);
  EXPECT_GT(up_z(), 0.8);
  EXPECT_EQ(mc_.machine().status().switch_status, SwitchStatus::EmergencyStop);
  // cleared: a restarted client (its err_flag starts with bit1 set, so it starts from the pose it
  // finds) drives the motors again and stands the robot back up
  mc_.faults()->request(parse_fault("clear").request.value());
  ExampleClient again;
  again.next(mc_.loop().last_cycle().state, kMotorSdkCommandLost);
  run(9.0, &again);
  EXPECT_EQ(mc_.loop().last_cycle().safety.flags & (kGuardHealthDamping | kGuardHealthStopped), 0u);
  EXPECT_GE(height_m(), 0.2);
}

TEST_F(MotorSdkLockstep, AnOverCurrentShowsItsPhasesBitAndAnOverloadItsOwnBitOnTheWire) {
  // the driver names the phase (seed: bit 5 phase B, bit 17 phase A) and one of the overload bits
  // 9..16; the client sees exactly the one raised, in spi_data and in robot_control_response
  run(0.5, nullptr);
  ExampleClient client;
  run(1.0, &client);
  ASSERT_EQ(mc_.arbiter().latched(), &source_);
  ASSERT_EQ(mc_.faults()->request(parse_fault("motor FL_hip over_current B").request.value()), "");
  ASSERT_EQ(mc_.faults()->request(parse_fault("motor RR_knee overload 8").request.value()), "");
  run(0.1, &client);
  const CycleRecord& record = mc_.loop().last_cycle();
  const spi_data_t spi = make_spi_data(record.state);
  const robot_control_response_lcmt response = make_response(record.high_level.status);
  // each faulted driver has stopped its motor (reset, bits 30..31 = 0) and carries its one bit
  constexpr std::size_t kOverCurrentMotor = 4, kOverloadMotor = 8;
  EXPECT_EQ(static_cast<std::uint32_t>(spi.flags[kOverCurrentMotor]), 1u << 5);
  EXPECT_EQ(static_cast<std::uint32_t>(response.motor_error[kOverCurrentMotor]), 1u << 5);
  EXPECT_EQ(static_cast<std::uint32_t>(spi.flags[kOverloadMotor]), 1u << 16);
  EXPECT_EQ(static_cast<std::uint32_t>(response.motor_error[kOverloadMotor]), 1u << 16);
  EXPECT_EQ(static_cast<std::uint32_t>(spi.flags[0]), kMotorErrorWordHealthy);
  // read back on the client side as exactly what was injected
  EXPECT_EQ(motor_faults_from_word(static_cast<std::uint32_t>(spi.flags[kOverCurrentMotor])), kMotorOverCurrentPhaseB);
  EXPECT_EQ(motor_faults_from_word(static_cast<std::uint32_t>(spi.flags[kOverloadMotor])), motor_overload(8));
  // the shared memory has one over-current bit for every phase (bit 2), and no bit for an overload
  const auto shm_fault_bits = [&](std::size_t i) {
    return static_cast<std::uint32_t>(shm_joint_state_flags(record.state.temperature_c[i], record.state.motor_faults[i],
                                                            24.0, record.state.driver_mode[i])) &
           0xFFu;
  };
  EXPECT_EQ(shm_fault_bits(kOverCurrentMotor), JOINT_STATE_OVER_CURRENT);
  EXPECT_EQ(shm_fault_bits(kOverloadMotor), 0u);
  // and the robot is protected as for any motor error
  EXPECT_EQ(record.safety.flags, kGuardHealthDamping);
}

TEST_F(MotorSdkLockstep, StandingRobotIsNotHandedOver) {
  McConfig config = default_config();
  config.startup = Startup::Stand;
  Mc standing = make_simulated_mc(config);
  MotorSdkSource source{MotorSdkParameters{}};
  standing.arbiter().add_low_level_source(source);
  for (int k = 0; k < 100; ++k) {
    ASSERT_EQ(source.mailbox().push(JointCommand{}, standing.loop().last_cycle().state.time_s), PushResult::Accepted);
    standing.loop().tick();
  }
  EXPECT_EQ(standing.arbiter().latched(), nullptr);
  EXPECT_FALSE(source.status().motor_mode);
  EXPECT_EQ(source.counters().frames_refused, 100u);
}

}  // namespace
}  // namespace cerebellum
