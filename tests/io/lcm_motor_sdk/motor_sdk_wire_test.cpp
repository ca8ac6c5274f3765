// Wire translation of the motor SDK channels: decode with reasons, signs, units, flags, and the
// foot quantities of leg_control_data checked against finite differences of the kinematics.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"
#include "io/lcm_motor_sdk/motor_sdk_wire.hpp"
#include "io/lcm_motor_sdk/robot_state_messages.hpp"

namespace cerebellum {
namespace {

std::vector<std::uint8_t> encoded(const motor_ctrl_lcmt& message) {
  std::vector<std::uint8_t> bytes(message.getEncodedSize());
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

JointCommand distinct_command() {
  JointCommand command;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    command.q_des[i] = 0.1 * (i + 1);
    command.qd_des[i] = -0.2 * (i + 1);
    command.kp[i] = 3.0 * (i + 1);
    command.kd[i] = 0.25 * (i + 1);
    command.tau_ff[i] = 0.5 - 0.1 * i;
  }
  return command;
}

RobotState distinct_state() {
  RobotState state;
  state.valid = true;
  state.time_s = 12.345678;
  state.q = robot::whole_body_pose(robot::kStandPose);
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    state.q[i] += 0.01 * i;
    state.qd[i] = 0.3 - 0.05 * i;
    state.tau[i] = -1.0 + 0.2 * i;
    state.temperature_c[i] = 30.0 + i;
  }
  return state;
}

TEST(MotorSdkWire, MotorCtrlRoundTripsWithHipAndKneeNegatedOnTheWire) {
  const JointCommand sdk = distinct_command();
  const motor_ctrl_lcmt message = encode_motor_ctrl(sdk);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const std::size_t abad = 3 * leg, hip = 3 * leg + 1, knee = 3 * leg + 2;
    EXPECT_FLOAT_EQ(message.q_des[abad], float(sdk.q_des[abad]));
    EXPECT_FLOAT_EQ(message.q_des[hip], -float(sdk.q_des[hip]));
    EXPECT_FLOAT_EQ(message.qd_des[knee], -float(sdk.qd_des[knee]));
    EXPECT_FLOAT_EQ(message.tau_des[knee], -float(sdk.tau_ff[knee]));
    EXPECT_FLOAT_EQ(message.kp_des[hip], float(sdk.kp[hip]));  // gains never flip
    EXPECT_FLOAT_EQ(message.kd_des[knee], float(sdk.kd[knee]));
  }
  const std::vector<std::uint8_t> bytes = encoded(message);
  ASSERT_EQ(bytes.size(), 248u);
  JointCommand decoded;
  ASSERT_EQ(decode_motor_ctrl(bytes.data(), bytes.size(), decoded), WireDecode::Ok);
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    EXPECT_NEAR(decoded.q_des[i], sdk.q_des[i], 1e-6);
    EXPECT_NEAR(decoded.qd_des[i], sdk.qd_des[i], 1e-6);
    EXPECT_NEAR(decoded.kp[i], sdk.kp[i], 1e-5);
    EXPECT_NEAR(decoded.kd[i], sdk.kd[i], 1e-6);
    EXPECT_NEAR(decoded.tau_ff[i], sdk.tau_ff[i], 1e-6);
  }
}

TEST(MotorSdkWire, MalformedPacketsAreClassified) {
  std::vector<std::uint8_t> bytes = encoded(encode_motor_ctrl(distinct_command()));
  JointCommand out;
  EXPECT_EQ(decode_motor_ctrl(bytes.data(), 100, out), WireDecode::Truncated);
  EXPECT_EQ(decode_motor_ctrl(bytes.data(), 7, out), WireDecode::Truncated);
  EXPECT_EQ(decode_motor_ctrl(bytes.data(), 247, out), WireDecode::Truncated);
  std::vector<std::uint8_t> longer = bytes;
  longer.resize(300, 0);
  EXPECT_EQ(decode_motor_ctrl(longer.data(), longer.size(), out), WireDecode::Oversized);
  std::vector<std::uint8_t> other = bytes;
  other[3] ^= 0x40;
  EXPECT_EQ(decode_motor_ctrl(other.data(), other.size(), out), WireDecode::WrongFingerprint);
  // the fingerprint of the vendor's type, as published
  EXPECT_EQ(static_cast<std::uint64_t>(motor_ctrl_lcmt::getHash()), 0x7bb7cc457845acacull);
}

TEST(MotorSdkWire, SpiDataCarriesWireJointsTenthsOfDegreesAndMotorFlags) {
  RobotState state = distinct_state();
  state.temperature_c[4] = 36.46;
  state.temperature_c[7] = 83.0;
  state.temperature_c[10] = 88.0;
  state.motor_faults[7] = kMotorTemperatureWarning;
  state.motor_faults[10] = kMotorTemperatureWarning | kMotorOverTemperature;
  state.motor_faults[11] = kMotorDisconnected | kMotorEncoderLost;
  const spi_data_t message = make_spi_data(state);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    EXPECT_FLOAT_EQ(message.q_abad[leg], float(state.q[3 * leg]));
    EXPECT_FLOAT_EQ(message.q_hip[leg], -float(state.q[3 * leg + 1]));
    EXPECT_FLOAT_EQ(message.q_knee[leg], -float(state.q[3 * leg + 2]));
    EXPECT_FLOAT_EQ(message.qd_hip[leg], -float(state.qd[3 * leg + 1]));
    EXPECT_FLOAT_EQ(message.tau_abad[leg], float(state.tau[3 * leg]));
    EXPECT_FLOAT_EQ(message.tau_knee[leg], -float(state.tau[3 * leg + 2]));
  }
  EXPECT_EQ(message.tmp_abad[0], 300);
  EXPECT_EQ(message.tmp_hip[1], 365);  // joint 4: 36.46 deg C
  EXPECT_EQ(message.tmp_hip[2], 830);  // joint 7
  EXPECT_EQ(static_cast<std::uint32_t>(message.flags[0]), 0x80000000u);
  EXPECT_EQ(static_cast<std::uint32_t>(message.flags[7]), 0x81000000u);   // warning bit 24
  EXPECT_EQ(static_cast<std::uint32_t>(message.flags[10]), 0x81000002u);  // and error bit 1
  EXPECT_EQ(static_cast<std::uint32_t>(message.flags[11]), 0x80000101u);  // bits 0 and 8
}

TEST(MotorSdkWire, MotorCtrlStateCarriesErrFlagAndInterval) {
  MotorSdkStatus status;
  status.err_flag = kMotorSdkCommandLate | kMotorSdkKneeJump;
  status.ctrl_topic_interval_ms = 2.5;
  const motor_ctrl_state_lcmt message = make_motor_ctrl_state(status);
  EXPECT_EQ(message.err_flag, 0x11);
  EXPECT_FLOAT_EQ(message.ctrl_topic_interval, 2.5f);
}

TEST(MotorSdkWire, StateEstimatorQuaternionIsWxyz) {
  RobotState state = distinct_state();
  state.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()));
  state.rpy = Eigen::Vector3d(0.0, 0.0, 0.3);
  state.position_world = Eigen::Vector3d(1.0, 2.0, 0.25);
  state.specific_force_body = Eigen::Vector3d(0.1, 0.2, 9.3);
  state.contact = {1.0, 0.0, 1.0, 0.0};
  const state_estimator_lcmt message = make_state_estimator(state);
  EXPECT_FLOAT_EQ(message.quat[0], float(std::cos(0.15)));
  EXPECT_FLOAT_EQ(message.quat[1], 0.0f);
  EXPECT_FLOAT_EQ(message.quat[3], float(std::sin(0.15)));
  EXPECT_FLOAT_EQ(message.rpy[2], 0.3f);
  EXPECT_FLOAT_EQ(message.p[2], 0.25f);
  // the accelerometer as it reads, and the same turned into the world (gravity included in both)
  EXPECT_FLOAT_EQ(message.aBody[1], 0.2f);
  EXPECT_FLOAT_EQ(message.aWorld[0], float(0.1 * std::cos(0.3) - 0.2 * std::sin(0.3)));
  EXPECT_FLOAT_EQ(message.aWorld[1], float(0.1 * std::sin(0.3) + 0.2 * std::cos(0.3)));
  EXPECT_FLOAT_EQ(message.aWorld[2], 9.3f);
  EXPECT_FLOAT_EQ(message.contactEstimate[1], 0.0f);
  EXPECT_FLOAT_EQ(message.contactEstimate[2], 1.0f);
  EXPECT_EQ(message.timestamp, 12345678000ll);
}

// d(foot)/dq by central differences, independent of the analytic Jacobian
Mat3 numeric_jacobian(std::size_t leg, const Vec3& q) {
  const double h = 1e-6;
  Mat3 jacobian;
  for (int j = 0; j < 3; ++j) {
    Vec3 plus = q, minus = q;
    plus[j] += h;
    minus[j] -= h;
    jacobian.col(j) = (foot_position_in_hip(leg, plus) - foot_position_in_hip(leg, minus)) / (2 * h);
  }
  return jacobian;
}

TEST(MotorSdkWire, LegControlDataFeetMatchTheKinematics) {
  const RobotState state = distinct_state();
  JointCommand command;
  for (std::size_t i = 0; i < kNumJoints; ++i) command.tau_ff[i] = 0.4 - 0.07 * i;
  const leg_control_data_lcmt message = make_leg_control_data(state, command);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Vec3 q(state.q[3 * leg], state.q[3 * leg + 1], state.q[3 * leg + 2]);
    const Vec3 qd(state.qd[3 * leg], state.qd[3 * leg + 1], state.qd[3 * leg + 2]);
    const Vec3 tau(state.tau[3 * leg], state.tau[3 * leg + 1], state.tau[3 * leg + 2]);
    const Vec3 tau_ff(command.tau_ff[3 * leg], command.tau_ff[3 * leg + 1], command.tau_ff[3 * leg + 2]);
    const Mat3 jacobian = numeric_jacobian(leg, q);
    const Vec3 p = foot_position_in_hip(leg, q);
    const Vec3 v = jacobian * qd;
    const Vec3 force(message.force_est[3 * leg], message.force_est[3 * leg + 1], message.force_est[3 * leg + 2]);
    const Vec3 force_desired(message.force_desired[3 * leg], message.force_desired[3 * leg + 1],
                             message.force_desired[3 * leg + 2]);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(message.p[3 * leg + k], p[k], 1e-6);
      EXPECT_NEAR(message.v[3 * leg + k], v[k], 1e-5);
    }
    // the forces reproduce the torques through J^T
    EXPECT_LT((jacobian.transpose() * force - tau).norm(), 1e-4);
    EXPECT_LT((jacobian.transpose() * force_desired - tau_ff).norm(), 1e-4);
    EXPECT_FLOAT_EQ(message.q[3 * leg + 1], -float(q[1]));
    EXPECT_FLOAT_EQ(message.qd[3 * leg], float(qd[0]));
    EXPECT_FLOAT_EQ(message.tau_est[3 * leg + 2], -float(tau[2]));
  }
}

}  // namespace
}  // namespace cerebellum
