// The translation between lowlevel.h frames and the MC's value types.
#include "io/shm_lowlevel/shm_codec.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace cerebellum {
namespace {

TEST(ShmCodec, JointStateFlagsPackEnableTemperatureAndVoltage) {
  // bit0 enabled; byte 1: 25 deg C + 40 = 65 = 0x41; byte 2: 24 V = 0x18
  EXPECT_EQ(shm_joint_state_flags(25.0, kMotorOk, 24.0), 0x00184101);
  EXPECT_EQ(shm_joint_state_flags(24.6, kMotorOk, 24.0), 0x00184101);  // rounded to whole degrees
  EXPECT_EQ(shm_joint_state_flags(-40.0, kMotorOk, 24.0), 0x00180001);
  EXPECT_EQ(shm_joint_state_flags(-60.0, kMotorOk, 24.0), 0x00180001);  // below the range: clamped
  EXPECT_EQ(shm_joint_state_flags(215.0, kMotorOk, 24.0), 0x0018FF01);
  EXPECT_EQ(shm_joint_state_flags(400.0, kMotorOk, 24.0), 0x0018FF01);
  EXPECT_EQ(shm_joint_state_flags(std::nan(""), kMotorOk, 24.0), 0x00180001);
}

TEST(ShmCodec, JointStateFlagsReportAMotorsFaultsTheWayTheOtherInterfacesDo) {
  // lowlevel.h: bit1 over-voltage, bit2 over-current, bit3 over-temperature, bit5 encoder fault;
  // a driver stopped by any error is not enabled (bit0 clear); the bus voltage is the battery's
  const auto flags = [](std::uint32_t faults, double volts = 24.0) {
    return static_cast<std::uint32_t>(shm_joint_state_flags(25.0, faults, volts)) & 0xFFu;
  };
  EXPECT_EQ(flags(kMotorOk), 0x01u);
  EXPECT_EQ(flags(kMotorTemperatureWarning), 0x01u);  // a warning: still enabled
  EXPECT_EQ(flags(kMotorOverTemperature | kMotorTemperatureWarning), 0x08u);
  EXPECT_EQ(flags(kMotorOverVoltage), 0x02u);
  // one over-current bit for any phase; an overload of any kind has no bit: not enabled
  for (MotorPhase phase : {MotorPhase::A, MotorPhase::B, MotorPhase::C}) {
    EXPECT_EQ(flags(motor_over_current(phase)), 0x04u);
  }
  EXPECT_EQ(flags(motor_overload(1)), 0x00u);
  EXPECT_EQ(flags(motor_overload(8)), 0x00u);
  EXPECT_EQ(flags(kMotorEncoderLost), 0x20u);
  EXPECT_EQ(flags(kMotorDisconnected), 0x00u);
  EXPECT_EQ(flags(kMotorDriverFault), 0x00u);
  EXPECT_EQ(static_cast<std::uint32_t>(shm_joint_state_flags(25.0, kMotorOk, 17.4)) >> 16, 17u);
}

SensorFrame numbered_frame() {
  SensorFrame frame;
  frame.time_s = 1.234;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    frame.q[i] = 0.1 * static_cast<double>(i) - 0.5;
    frame.qd[i] = 2.0 + static_cast<double>(i);
    frame.tau[i] = -1.0 - 0.25 * static_cast<double>(i);
    frame.temperature_c[i] = 30.0 + static_cast<double>(i);
  }
  frame.imu_quat = {0.9, 0.1, -0.2, 0.3};
  frame.imu_gyro = {0.01, -0.02, 0.03};
  frame.imu_accel = {0.5, -0.4, 9.7};
  return frame;
}

TEST(ShmCodec, LegsKeepTheSdkConventionAndZeroTheFoot) {
  const SensorFrame frame = numbered_frame();
  leg_state_t legs[kNumLegs];
  std::memset(legs, 0x5a, sizeof(legs));  // garbage that must be overwritten, foot included
  encode_shm_legs(frame, legs);
  const joint_state_t* joints[kNumLegs][3];
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    joints[leg][0] = &legs[leg].abad;
    joints[leg][1] = &legs[leg].hip;
    joints[leg][2] = &legs[leg].knee;
    EXPECT_EQ(legs[leg].foot.flags, 0);
    EXPECT_EQ(legs[leg].foot.p, 0.0f);
    EXPECT_EQ(legs[leg].foot.v, 0.0f);
    EXPECT_EQ(legs[leg].foot.t, 0.0f);
  }
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    const joint_state_t& j = *joints[i / 3][i % 3];
    // no sign flip: the frame's numbers, rounded to float
    EXPECT_EQ(j.p, static_cast<float>(0.1 * static_cast<double>(i) - 0.5)) << i;
    EXPECT_EQ(j.v, static_cast<float>(2.0 + static_cast<double>(i))) << i;
    EXPECT_EQ(j.t, static_cast<float>(-1.0 - 0.25 * static_cast<double>(i))) << i;
    EXPECT_EQ((j.flags >> 8) & 0xff, 70 + static_cast<int>(i)) << i;  // 30 + i deg C, + 40
  }
  // FRONT_LEFT is the second leg of the array, as in the project's FR, FL, RR, RL order
  EXPECT_EQ(legs[FRONT_LEFT].hip.p, static_cast<float>(frame.q[joint_index(Leg::FL, Joint::Hip)]));
  EXPECT_EQ(legs[BACK_LEFT].knee.p, static_cast<float>(frame.q[joint_index(Leg::RL, Joint::Knee)]));
}

TEST(ShmCodec, ImuCarriesRobotTimeInNanosecondsAndWxyz) {
  const SensorFrame frame = numbered_frame();
  nav_imu_t imu{};
  encode_shm_imu(frame, imu);
  EXPECT_EQ(imu.timestamp, 1234000000u);
  EXPECT_EQ(imu.q[0], 0.9f);
  EXPECT_EQ(imu.q[1], 0.1f);
  EXPECT_EQ(imu.q[2], -0.2f);
  EXPECT_EQ(imu.q[3], 0.3f);
  EXPECT_EQ(imu.gyro[1], -0.02f);
  EXPECT_EQ(imu.acc[2], 9.7f);
  EXPECT_EQ(shm_timestamp_ns(0.001), 1000000u);
  EXPECT_EQ(shm_timestamp_ns(-1.0), 0u);
}

// every joint at p_des = index / 10, gains 60 / 2, t_ff = -index / 100
void fill_command(leg_control_t (&legs)[kNumLegs]) {
  std::memset(legs, 0, sizeof(legs));
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    joint_control_t* joints[3] = {&legs[leg].abad, &legs[leg].hip, &legs[leg].knee};
    for (std::size_t j = 0; j < 3; ++j) {
      const auto i = static_cast<float>(3 * leg + j);
      joints[j]->p_des = i / 10.0f;
      joints[j]->v_des = 0.5f;
      joints[j]->kp = 60.0f;
      joints[j]->kd = 2.0f;
      joints[j]->t_ff = -i / 100.0f;
    }
    legs[leg].flags = 1;
  }
}

TEST(ShmCodec, AFrameBecomesTheCommandWithoutSignFlip) {
  leg_control_t legs[kNumLegs];
  fill_command(legs);
  legs[BACK_RIGHT].foot.kp = std::numeric_limits<float>::quiet_NaN();  // the foot is not read
  const JointCommand command = decode_shm_command(legs);
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    EXPECT_EQ(command.q_des[i], static_cast<float>(i) / 10.0f) << i;
    EXPECT_EQ(command.qd_des[i], 0.5) << i;
    EXPECT_EQ(command.kp[i], 60.0) << i;
    EXPECT_EQ(command.kd[i], 2.0) << i;
    EXPECT_EQ(command.tau_ff[i], -static_cast<float>(i) / 100.0f) << i;
  }
}

// the translation judges nothing: the source (lowlevel/shm) checks the frame and names the value
// the client wrote, so a NaN or an absurd gain must arrive as written, in its joint and field
TEST(ShmCodec, EveryValueArrivesAsTheClientWroteIt) {
  leg_control_t legs[kNumLegs];
  fill_command(legs);
  legs[FRONT_LEFT].hip.p_des = std::numeric_limits<float>::quiet_NaN();
  legs[FRONT_RIGHT].abad.v_des = -std::numeric_limits<float>::infinity();
  legs[BACK_RIGHT].hip.kp = 1e6f;
  legs[BACK_RIGHT].abad.kd = -0.1f;
  legs[BACK_LEFT].abad.t_ff = std::numeric_limits<float>::infinity();
  const JointCommand command = decode_shm_command(legs);
  EXPECT_TRUE(std::isnan(command.q_des[joint_index(Leg::FL, Joint::Hip)]));
  EXPECT_EQ(command.qd_des[joint_index(Leg::FR, Joint::Abad)], -std::numeric_limits<double>::infinity());
  EXPECT_EQ(command.kp[joint_index(Leg::RR, Joint::Hip)], 1e6);
  EXPECT_EQ(command.kd[joint_index(Leg::RR, Joint::Abad)], static_cast<double>(-0.1f));
  EXPECT_EQ(command.tau_ff[joint_index(Leg::RL, Joint::Abad)], std::numeric_limits<double>::infinity());
}

// the client's side (a ZsiBot driven through its daemon): the flags word read bit by bit as
// lowlevel.h lays it out, written here by hand, not by the encoder
TEST(ShmCodec, AClientReadsTheFlagsWordsTemperatureFaultsAndEnableAsTheHeaderLaysThemOut) {
  const std::int32_t enabled_at_55c = static_cast<std::int32_t>((95u << 8) | (24u << 16) | 1u);
  EXPECT_DOUBLE_EQ(shm_temperature_c(enabled_at_55c), 55.0);
  EXPECT_EQ(shm_motor_faults(enabled_at_55c), kMotorOk);
  EXPECT_EQ(shm_driver_mode(enabled_at_55c), MotorDriverMode::Motor);
  const std::int32_t hot_and_off = static_cast<std::int32_t>((0u << 8) | (1u << 3));
  EXPECT_DOUBLE_EQ(shm_temperature_c(hot_and_off), -40.0);
  EXPECT_EQ(shm_motor_faults(hot_and_off), kMotorOverTemperature);
  EXPECT_EQ(shm_driver_mode(hot_and_off), MotorDriverMode::Reset);
  EXPECT_EQ(shm_motor_faults(1 << 1), kMotorOverVoltage);
  EXPECT_EQ(shm_motor_faults(1 << 2), kMotorOverCurrentAnyPhase) << "the header does not name the phase";
  EXPECT_EQ(shm_motor_faults(1 << 4), kMotorOverSpeed);
  EXPECT_EQ(shm_motor_faults(1 << 5), kMotorEncoderLost);
}

TEST(ShmCodec, WhatTheDaemonWritesAClientReadsBackWithinFloatPrecision) {
  SensorFrame frame;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    frame.q[i] = 0.1 * static_cast<double>(i) - 0.5;
    frame.qd[i] = -0.2 * static_cast<double>(i);
    frame.tau[i] = 0.7 * static_cast<double>(i) - 3.0;
    frame.temperature_c[i] = 30.0 + static_cast<double>(i);
  }
  frame.motor_faults[4] = kMotorEncoderLost;
  frame.driver_mode[9] = MotorDriverMode::Reset;
  frame.imu_quat = {0.9, 0.1, -0.3, 0.2};
  frame.imu_gyro = {0.4, -0.5, 0.6};
  frame.imu_accel = {0.1, 0.2, 9.81};
  leg_state_t legs[kNumLegs]{};
  encode_shm_legs(frame, legs);
  const JointReading joints = decode_shm_legs(legs);
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    EXPECT_NEAR(joints.q[i], frame.q[i], 1e-6) << i;
    EXPECT_NEAR(joints.qd[i], frame.qd[i], 1e-6) << i;
    EXPECT_NEAR(joints.tau[i], frame.tau[i], 1e-6) << i;
    EXPECT_DOUBLE_EQ(joints.temperature_c[i], frame.temperature_c[i]) << i;
  }
  EXPECT_EQ(joints.motor_faults[4], kMotorEncoderLost);
  EXPECT_EQ(joints.driver_mode[4], MotorDriverMode::Reset) << "a motor with an error is not enabled";
  EXPECT_EQ(joints.driver_mode[9], MotorDriverMode::Reset);
  EXPECT_EQ(joints.driver_mode[0], MotorDriverMode::Motor);
  nav_imu_t imu{};
  encode_shm_imu(frame, imu);
  const ImuReading read = decode_shm_imu(imu);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(read.quat[k], frame.imu_quat[k], 1e-6) << k;
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(read.gyro_rad_s[k], frame.imu_gyro[k], 1e-6) << k;
    EXPECT_NEAR(read.specific_force_m_s2[k], frame.imu_accel[k], 1e-6) << k;
  }
}

TEST(ShmCodec, AClientsCommandFrameSetsEveryLegsFlagZeroesTheFootAndDecodesToTheCommand) {
  JointCommand command;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    command.q_des[i] = 0.05 * static_cast<double>(i);
    command.qd_des[i] = -0.1 * static_cast<double>(i);
    command.kp[i] = 10.0 + static_cast<double>(i);
    command.kd[i] = 0.5 + 0.1 * static_cast<double>(i);
    command.tau_ff[i] = 1.5 - 0.25 * static_cast<double>(i);
  }
  leg_control_t legs[kNumLegs];
  std::memset(legs, 0x7f, sizeof legs);  // whatever was there before
  encode_shm_command(command, legs);
  for (const leg_control_t& leg : legs) {
    EXPECT_EQ(leg.flags, 1);
    EXPECT_EQ(leg.foot.kp, 0.0f);
    EXPECT_EQ(leg.foot.p_des, 0.0f);
  }
  EXPECT_FLOAT_EQ(legs[static_cast<std::size_t>(Leg::RL)].knee.kp,
                  static_cast<float>(command.kp[joint_index(Leg::RL, Joint::Knee)]));
  const JointCommand read = decode_shm_command(legs);
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    EXPECT_NEAR(read.q_des[i], command.q_des[i], 1e-6) << i;
    EXPECT_NEAR(read.qd_des[i], command.qd_des[i], 1e-6) << i;
    EXPECT_NEAR(read.kp[i], command.kp[i], 1e-5) << i;
    EXPECT_NEAR(read.kd[i], command.kd[i], 1e-6) << i;
    EXPECT_NEAR(read.tau_ff[i], command.tau_ff[i], 1e-6) << i;
  }
}

}  // namespace
}  // namespace cerebellum
