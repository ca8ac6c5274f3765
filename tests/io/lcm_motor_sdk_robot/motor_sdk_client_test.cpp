// The motor SDK client's rules on the MC's types, without sockets: activation by all-zero frames,
// the stop on a motor error, the vendor's ranges and position-jump steps, the 20 ms link watch,
// and the wire's sign convention both ways.
#include "io/lcm_motor_sdk_robot/motor_sdk_client.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/robot_model.hpp"
#include "io/lcm_motor_sdk/motor_sdk_wire.hpp"
#include "io/lcm_motor_sdk/robot_state_messages.hpp"
#include "io/robot_link/lying_robot.hpp"

namespace cerebellum {
namespace {

// a stiff command holding the lying pose
JointCommand holding_command() {
  JointCommand command;
  command.q_des = lying_joints().q;
  command.kp.fill(60.0);
  command.kd.fill(2.0);
  return command;
}

bool all_zero(const JointCommand& frame) {
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    if (frame.kp[i] != 0.0 || frame.kd[i] != 0.0 || frame.tau_ff[i] != 0.0) return false;
  }
  return true;
}

// the client with fresh joints and IMU at time now_s on the link's clock
MotorSdkClient heard_client(double now_s = 0.0) {
  MotorSdkClient client{MotorSdkRobotConfig{}};
  client.take_joints(lying_joints(), now_s);
  client.take_imu(ImuReading{}, now_s);
  return client;
}

TEST(MotorSdkClient, SendsAllZeroFramesUntilTheRobotClearsErrFlagBit1AndAgainWhenItComesBack) {
  MotorSdkClient client = heard_client();
  EXPECT_TRUE(all_zero(client.command(holding_command()))) << "the vendor's client starts as if bit 1 were set";
  client.take_err_flag(kMotorSdkCommandLost);
  EXPECT_TRUE(all_zero(client.command(holding_command())));
  client.take_err_flag(0);
  EXPECT_TRUE(client.status().activated);
  EXPECT_DOUBLE_EQ(client.command(holding_command()).kp[0], 60.0) << "activated: the MC's command goes out";
  client.take_err_flag(kMotorSdkCommandLost);
  EXPECT_TRUE(all_zero(client.command(holding_command()))) << "the robot lost our frames: activate again";
  EXPECT_EQ(client.status().zero_frames, 3u);
}

TEST(MotorSdkClient, StopsCommandingAtOnceWhenAMotorReportsAnErrorAndStaysStopped) {
  MotorSdkClient client = heard_client();
  client.take_err_flag(0);
  JointReading joints = lying_joints();
  joints.motor_faults[4] = kMotorTemperatureWarning;
  client.take_joints(joints, 0.002);
  EXPECT_FALSE(client.status().stopped) << "a warning is not an error";
  joints.motor_faults[4] = kMotorOverTemperature;
  client.take_joints(joints, 0.004);
  const JointCommand frame = client.command(holding_command());
  EXPECT_TRUE(client.status().stopped);
  EXPECT_EQ(client.status().error_motors, 1u << 4);
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    EXPECT_EQ(frame.kp[i], 0.0) << "joint " << i;
    EXPECT_EQ(frame.tau_ff[i], 0.0) << "joint " << i;
    EXPECT_DOUBLE_EQ(frame.kd[i], robot::kDampingKd) << "joint " << i;
  }
  client.take_joints(lying_joints(), 0.006);
  EXPECT_EQ(client.command(holding_command()).kp[0], 0.0) << "stopped until restart, as the vendor's client";
}

TEST(MotorSdkClient, KeepsTheCommandInsideTheVendorsRangesAndPositionJumps) {
  MotorSdkClient client = heard_client();
  client.take_err_flag(0);
  JointCommand command = holding_command();
  command.kp[0] = 500.0;                 // above kp 200
  command.tau_ff[1] = -30.0;             // below -12 Nm
  command.q_des[3] += robot::deg(20.0);  // an abad step of 20 degrees: 8 allowed
  command.q_des[5] += robot::deg(11.0);  // a knee step of 11 degrees: within 12
  client.frame(listened(0.0), 0.0);
  const JointCommand frame = client.command(command);
  EXPECT_DOUBLE_EQ(frame.kp[0], robot::kCommandKpMax);
  EXPECT_DOUBLE_EQ(frame.tau_ff[1], -robot::kTorqueMaxNm);
  EXPECT_NEAR(frame.q_des[3], lying_joints().q[3] + robot::deg(8.0), 1e-12);
  EXPECT_NEAR(frame.q_des[5], lying_joints().q[5] + robot::deg(11.0), 1e-12);
  EXPECT_EQ(client.status().range_clamps, 1u);
  EXPECT_EQ(client.status().jump_clamps, 1u);
}

TEST(MotorSdkClient, ReportsEveryMotorDisconnectedWhenNoStateCameFor20Ms) {
  MotorSdkClient client = heard_client(1.000);
  SensorFrame frame = client.frame(listened(1.019), 5.0);
  EXPECT_EQ(frame.motor_faults[0], kMotorOk) << "19 ms of silence is a healthy link";
  EXPECT_DOUBLE_EQ(frame.time_s, 5.0) << "stamped with the robot time";
  frame = client.frame(listened(1.021), 5.002);
  for (std::size_t i = 0; i < kNumJoints; ++i) EXPECT_TRUE(frame.motor_faults[i] & kMotorDisconnected) << i;
  EXPECT_TRUE(client.status().link_lost);
  EXPECT_EQ(client.status().link_losses, 1u);
  client.frame(listened(1.030), 5.004);
  EXPECT_EQ(client.status().link_losses, 1u) << "one loss, however long";
  // the IMU alone is not the link: spi_data must come too
  client.take_imu(live_imu(1.031), 1.031);
  EXPECT_TRUE(client.frame(listened(1.032), 5.006).motor_faults[0] & kMotorDisconnected);
  client.take_joints(live_joints(1.032), 1.032);
  EXPECT_EQ(client.frame(listened(1.033), 5.008).motor_faults[0], kMotorOk) << "fresh state: the link is back";
}

TEST(MotorSdkClient, ReadsTheWireInTheSdkConventionAndTheImuFromStateEstimator) {
  RobotState state;
  state.q = lying_joints().q;
  state.qd[1] = 0.5;
  state.tau[2] = -3.0;
  state.temperature_c[0] = 41.3;
  state.motor_faults[7] = kMotorOverTemperature;
  const spi_data_t wire = make_spi_data(state);
  EXPECT_FLOAT_EQ(wire.q_hip[0], static_cast<float>(-robot::kLyingPose[1])) << "hip and knee negated on the wire";
  const JointReading read = joint_state_from_spi_data(wire);
  for (std::size_t i = 0; i < kNumJoints; ++i) EXPECT_NEAR(read.q[i], state.q[i], 1e-6) << i;
  EXPECT_NEAR(read.qd[1], 0.5, 1e-6);
  EXPECT_NEAR(read.tau[2], -3.0, 1e-6);
  EXPECT_NEAR(read.temperature_c[0], 41.3, 1e-9);
  EXPECT_EQ(read.motor_faults[7], kMotorOverTemperature);
  EXPECT_EQ(read.driver_mode[0], MotorDriverMode::Motor);

  state.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()));
  state.omega_body = {0.1, -0.2, 0.3};
  state.specific_force_body = {0.0, 0.5, 9.81};
  const ImuReading imu = imu_from_state_estimator(make_state_estimator(state));
  EXPECT_NEAR(imu.quat[0], state.orientation.w(), 1e-6) << "quat is (w, x, y, z)";
  EXPECT_NEAR(imu.quat[3], state.orientation.z(), 1e-6);
  EXPECT_NEAR(imu.gyro_rad_s[2], 0.3, 1e-6);
  EXPECT_NEAR(imu.specific_force_m_s2[2], 9.81, 1e-5) << "the accelerometer as it reads, gravity included";
}

}  // namespace
}  // namespace cerebellum
