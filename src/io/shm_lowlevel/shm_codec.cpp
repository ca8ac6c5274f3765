#include "io/shm_lowlevel/shm_codec.hpp"

#include <algorithm>
#include <cmath>

namespace cerebellum {
namespace {

joint_state_t& joint_in(leg_state_t& leg, std::size_t joint) {
  switch (joint) {
    case 0: return leg.abad;
    case 1: return leg.hip;
    default: return leg.knee;
  }
}

const joint_state_t& joint_in(const leg_state_t& leg, std::size_t joint) {
  switch (joint) {
    case 0: return leg.abad;
    case 1: return leg.hip;
    default: return leg.knee;
  }
}

joint_control_t& joint_in(leg_control_t& leg, std::size_t joint) {
  switch (joint) {
    case 0: return leg.abad;
    case 1: return leg.hip;
    default: return leg.knee;
  }
}

const joint_control_t& joint_in(const leg_control_t& leg, std::size_t joint) {
  switch (joint) {
    case 0: return leg.abad;
    case 1: return leg.hip;
    default: return leg.knee;
  }
}

}  // namespace

namespace {

// a whole number clamped into one byte; 0 for NaN
std::uint32_t byte_of(double value) {
  return std::isfinite(value) ? static_cast<std::uint32_t>(std::clamp(std::round(value), 0.0, 255.0)) : 0u;
}

}  // namespace

std::int32_t shm_joint_state_flags(double temperature_c, std::uint32_t motor_faults, double bus_voltage_v,
                                   MotorDriverMode driver_mode) {
  std::uint32_t flags = (byte_of(temperature_c + JOINT_STATE_TEMPERATURE_OFFSET_C) << JOINT_STATE_TEMPERATURE_SHIFT) |
                        (byte_of(bus_voltage_v) << JOINT_STATE_BUS_VOLTAGE_SHIFT);
  if ((motor_faults & kMotorErrorBits) == 0 && driver_mode == MotorDriverMode::Motor) flags |= JOINT_STATE_ENABLED;
  if (motor_faults & kMotorOverSpeed) flags |= JOINT_STATE_OVER_SPEED;
  if (motor_faults & kMotorOverVoltage) flags |= JOINT_STATE_OVER_VOLTAGE;
  if (motor_faults & kMotorOverCurrentAnyPhase) flags |= JOINT_STATE_OVER_CURRENT;
  if (motor_faults & kMotorOverTemperature) flags |= JOINT_STATE_OVER_TEMPERATURE;
  if (motor_faults & kMotorEncoderLost) flags |= JOINT_STATE_ENCODER_FAULT;
  return static_cast<std::int32_t>(flags);
}

void encode_shm_legs(const SensorFrame& frame, leg_state_t (&legs)[kNumLegs]) {
  const double bus_voltage_v = frame.battery.present ? frame.battery.voltage_v : kShmNominalBusVoltageV;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    legs[leg].foot = joint_state_t{};
    for (std::size_t joint = 0; joint < kJointsPerLeg; ++joint) {
      const std::size_t i = joint_index(leg, joint);
      joint_state_t& out = joint_in(legs[leg], joint);
      out.flags =
          shm_joint_state_flags(frame.temperature_c[i], frame.motor_faults[i], bus_voltage_v, frame.driver_mode[i]);
      out.p = static_cast<float>(frame.q[i]);
      out.v = static_cast<float>(frame.qd[i]);
      out.t = static_cast<float>(frame.tau[i]);
    }
  }
}

std::uint64_t shm_timestamp_ns(double time_s) {
  return time_s > 0.0 ? static_cast<std::uint64_t>(std::llround(time_s * 1e9)) : 0;
}

void encode_shm_imu(const SensorFrame& frame, nav_imu_t& imu) {
  imu.timestamp = shm_timestamp_ns(frame.time_s);
  for (std::size_t k = 0; k < 3; ++k) {
    imu.acc[k] = static_cast<float>(frame.imu_accel[k]);
    imu.gyro[k] = static_cast<float>(frame.imu_gyro[k]);
  }
  for (std::size_t k = 0; k < 4; ++k) imu.q[k] = static_cast<float>(frame.imu_quat[k]);
}

JointCommand decode_shm_command(const leg_control_t (&legs)[kNumLegs]) {
  JointCommand command;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    for (std::size_t joint = 0; joint < kJointsPerLeg; ++joint) {
      const std::size_t i = joint_index(leg, joint);
      const joint_control_t& in = joint_in(legs[leg], joint);
      command.q_des[i] = in.p_des;
      command.qd_des[i] = in.v_des;
      command.kp[i] = in.kp;
      command.kd[i] = in.kd;
      command.tau_ff[i] = in.t_ff;
    }
  }
  return command;
}

MotorDriverMode shm_driver_mode(std::int32_t flags) {
  return (static_cast<std::uint32_t>(flags) & JOINT_STATE_ENABLED) ? MotorDriverMode::Motor : MotorDriverMode::Reset;
}

std::uint32_t shm_motor_faults(std::int32_t flags) {
  const auto bits = static_cast<std::uint32_t>(flags);
  std::uint32_t faults = kMotorOk;
  if (bits & JOINT_STATE_OVER_VOLTAGE) faults |= kMotorOverVoltage;
  if (bits & JOINT_STATE_OVER_CURRENT) faults |= kMotorOverCurrentAnyPhase;
  if (bits & JOINT_STATE_OVER_TEMPERATURE) faults |= kMotorOverTemperature;
  if (bits & JOINT_STATE_OVER_SPEED) faults |= kMotorOverSpeed;
  if (bits & JOINT_STATE_ENCODER_FAULT) faults |= kMotorEncoderLost;
  return faults;
}

double shm_temperature_c(std::int32_t flags) {
  return static_cast<double>((static_cast<std::uint32_t>(flags) >> JOINT_STATE_TEMPERATURE_SHIFT) & 0xffu) -
         JOINT_STATE_TEMPERATURE_OFFSET_C;
}

JointReading decode_shm_legs(const leg_state_t (&legs)[kNumLegs]) {
  JointReading reading;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    for (std::size_t joint = 0; joint < kJointsPerLeg; ++joint) {
      const std::size_t i = joint_index(leg, joint);
      const joint_state_t& in = joint_in(legs[leg], joint);
      reading.q[i] = in.p;
      reading.qd[i] = in.v;
      reading.tau[i] = in.t;
      reading.temperature_c[i] = shm_temperature_c(in.flags);
      reading.motor_faults[i] = shm_motor_faults(in.flags);
      reading.driver_mode[i] = shm_driver_mode(in.flags);
    }
  }
  return reading;
}

ImuReading decode_shm_imu(const nav_imu_t& imu) {
  ImuReading reading;
  for (std::size_t k = 0; k < 3; ++k) {
    reading.specific_force_m_s2[k] = imu.acc[k];
    reading.gyro_rad_s[k] = imu.gyro[k];
  }
  for (std::size_t k = 0; k < 4; ++k) reading.quat[k] = imu.q[k];
  return reading;
}

void encode_shm_command(const JointCommand& command, leg_control_t (&legs)[kNumLegs]) {
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    legs[leg].foot = joint_control_t{};
    legs[leg].flags = 1;
    for (std::size_t joint = 0; joint < kJointsPerLeg; ++joint) {
      const std::size_t i = joint_index(leg, joint);
      joint_control_t& out = joint_in(legs[leg], joint);
      out.p_des = static_cast<float>(command.q_des[i]);
      out.v_des = static_cast<float>(command.qd_des[i]);
      out.kp = static_cast<float>(command.kp[i]);
      out.kd = static_cast<float>(command.kd[i]);
      out.t_ff = static_cast<float>(command.tau_ff[i]);
    }
  }
}

}  // namespace cerebellum
