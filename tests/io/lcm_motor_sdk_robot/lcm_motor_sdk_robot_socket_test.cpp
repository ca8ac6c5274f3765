// The motor SDK robot backend over real LCM sockets, inside a private network namespace, with the
// test playing the robot: hostile packets are refused and counted, the robot's state reaches the
// sensor frame in the SDK convention, and motor_ctrl goes out all-zero until the robot clears
// err_flag bit 1, then as the MC commands (wire convention).
#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <thread>
#include <vector>

#include "io/lcm_motor_sdk/motor_sdk_wire.hpp"
#include "io/common/eventually.hpp"
#include "io/lcm_motor_sdk/robot_state_messages.hpp"
#include "io/lcm_motor_sdk_robot/lcm_motor_sdk_robot.hpp"
#include "io/robot_link/lying_robot.hpp"

namespace cerebellum {
namespace {

// the robot's side of the link: publishes its state, keeps the newest motor_ctrl it received
struct FakeRobot {
  lcm::LCM control{MotorSdkRobotConfig{}.control_url};
  lcm::LCM estimator{MotorSdkRobotConfig{}.estimator_url};
  std::optional<motor_ctrl_lcmt> received;

  FakeRobot() { control.subscribe(kMotorCtrlChannel, &FakeRobot::on_motor_ctrl, this); }
  void on_motor_ctrl(const lcm::ReceiveBuffer*, const std::string&, const motor_ctrl_lcmt* message) {
    received = *message;
  }
  // one 2 ms tick of a robot in motor mode
  void publish(const RobotState& state, std::int16_t err_flag) {
    const spi_data_t spi = make_spi_data(state);
    control.publish(kSpiDataChannel, &spi);
    motor_ctrl_state_lcmt status{};
    status.err_flag = err_flag;
    control.publish(kMotorCtrlStateChannel, &status);
    const state_estimator_lcmt estimate = make_state_estimator(state);
    estimator.publish(kStateEstimatorChannel, &estimate);
    control.handleTimeout(1);
  }
};

RobotState lying_state() {
  RobotState state;
  state.q = lying_joint_angles();
  return state;
}

TEST(LcmMotorSdkRobot, RefusesAndCountsMalformedAndNonFinitePacketsFromTheRobot) {
  LcmMotorSdkRobot robot(MotorSdkRobotConfig{}, stderr);
  lcm::LCM control(MotorSdkRobotConfig{}.control_url);
  const std::vector<std::uint8_t> garbage(100, 0x5a);
  control.publish(kSpiDataChannel, garbage.data(), static_cast<unsigned>(garbage.size()));
  RobotState nan_state = lying_state();
  nan_state.q[4] = std::numeric_limits<double>::quiet_NaN();
  const spi_data_t nan_spi = make_spi_data(nan_state);
  control.publish(kSpiDataChannel, &nan_spi);
  ASSERT_TRUE(eventually([&] { return robot.rejections().malformed == 1 && robot.rejections().non_finite == 1; }))
      << robot.rejections().malformed << " malformed, " << robot.rejections().non_finite << " non-finite";
  EXPECT_TRUE(robot.read().motor_faults[4] & kMotorDisconnected) << "a refused packet is no state";
}

TEST(LcmMotorSdkRobot, ReadsTheRobotAndSendsAllZeroFramesUntilItClearsBit1ThenTheCommand) {
  LcmMotorSdkRobot robot(MotorSdkRobotConfig{}, stderr);
  FakeRobot fake;
  JointCommand command;
  command.q_des = lying_state().q;
  command.kp.fill(60.0);
  command.kd.fill(2.0);

  SensorFrame frame;
  ASSERT_TRUE(eventually([&] {
    fake.publish(lying_state(), kMotorSdkCommandLost);
    frame = robot.read();
    robot.write(command);
    return frame.motor_faults[0] == kMotorOk && fake.received.has_value();
  }));
  EXPECT_NEAR(frame.q[1], robot::kLyingPose[1], 1e-6) << "the hip in the SDK convention (negated on the wire)";
  EXPECT_EQ(fake.received->kp_des[0], 0.0f) << "err_flag bit 1: all-zero frames activate the robot";

  ASSERT_TRUE(eventually([&] {
    fake.publish(lying_state(), 0);
    robot.read();
    robot.write(command);
    return fake.received && fake.received->kp_des[0] == 60.0f;
  }));
  EXPECT_FLOAT_EQ(fake.received->q_des[1], static_cast<float>(-robot::kLyingPose[1])) << "sent in the wire convention";
  EXPECT_FLOAT_EQ(fake.received->kd_des[1], 2.0f);
}

}  // namespace
}  // namespace cerebellum
