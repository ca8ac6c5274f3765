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

const joint_control_t& joint_in(const leg_control_t& leg, std::size_t joint) {
  switch (joint) {
    case 0: return leg.abad;
    case 1: return leg.hip;
    default: return leg.knee;
  }
}

}  // namespace

std::int32_t shm_joint_state_flags(double temperature_c) {
  const double encoded = std::isfinite(temperature_c) ? std::clamp(std::round(temperature_c) + 40.0, 0.0, 255.0) : 0.0;
  const auto temperature_byte = static_cast<std::uint32_t>(encoded);
  const std::uint32_t flags = JOINT_STATE_ENABLED | (temperature_byte << JOINT_STATE_TEMPERATURE_SHIFT) |
                              (static_cast<std::uint32_t>(kShmBusVoltageV) << JOINT_STATE_BUS_VOLTAGE_SHIFT);
  return static_cast<std::int32_t>(flags);
}

void encode_shm_legs(const SensorFrame& frame, leg_state_t (&legs)[kNumLegs]) {
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    legs[leg].foot = joint_state_t{};
    for (std::size_t joint = 0; joint < kJointsPerLeg; ++joint) {
      const std::size_t i = joint_index(leg, joint);
      joint_state_t& out = joint_in(legs[leg], joint);
      out.flags = shm_joint_state_flags(frame.temperature_c[i]);
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

ShmCommandCheck decode_shm_command(const leg_control_t (&legs)[kNumLegs], const CommandLimits& limits,
                                   JointCommand& command) {
  // check the whole frame before touching the command
  JointCommand decoded;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    for (std::size_t joint = 0; joint < kJointsPerLeg; ++joint) {
      const std::size_t i = joint_index(leg, joint);
      const joint_control_t& in = joint_in(legs[leg], joint);
      decoded.q_des[i] = in.p_des;
      decoded.qd_des[i] = in.v_des;
      decoded.kp[i] = in.kp;
      decoded.kd[i] = in.kd;
      decoded.tau_ff[i] = in.t_ff;
    }
  }
  const ShmCommandCheck check = check_shm_command(decoded, limits);
  if (check.ok()) command = decoded;
  return check;
}

}  // namespace cerebellum
