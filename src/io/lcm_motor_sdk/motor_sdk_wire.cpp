#include "io/lcm_motor_sdk/motor_sdk_wire.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "io/common/motor_error_word.hpp"

namespace cerebellum {
namespace {

// deg C to the wire's 0.1 deg C steps
std::int16_t tenths_of_degree(double temperature_c) {
  const double tenths = std::round(temperature_c * 10.0);
  const double bounded = std::clamp(tenths, double(std::numeric_limits<std::int16_t>::min()),
                                    double(std::numeric_limits<std::int16_t>::max()));
  return std::isfinite(bounded) ? static_cast<std::int16_t>(bounded) : std::int16_t{0};
}

}  // namespace

WireDecode decode_motor_ctrl(const void* data, std::size_t size, JointCommand& sdk_command) {
  motor_ctrl_lcmt message;
  if (const WireDecode checked = decode_fixed_size(data, size, message); checked != WireDecode::Ok) return checked;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    const double sign = wire_sign(i % kJointsPerLeg);
    sdk_command.q_des[i] = sign * message.q_des[i];
    sdk_command.qd_des[i] = sign * message.qd_des[i];
    sdk_command.kp[i] = message.kp_des[i];
    sdk_command.kd[i] = message.kd_des[i];
    sdk_command.tau_ff[i] = sign * message.tau_des[i];
  }
  return WireDecode::Ok;
}

motor_ctrl_lcmt encode_motor_ctrl(const JointCommand& sdk_command) {
  motor_ctrl_lcmt message;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    const double sign = wire_sign(i % kJointsPerLeg);
    message.q_des[i] = static_cast<float>(sign * sdk_command.q_des[i]);
    message.qd_des[i] = static_cast<float>(sign * sdk_command.qd_des[i]);
    message.kp_des[i] = static_cast<float>(sdk_command.kp[i]);
    message.kd_des[i] = static_cast<float>(sdk_command.kd[i]);
    message.tau_des[i] = static_cast<float>(sign * sdk_command.tau_ff[i]);
  }
  return message;
}

spi_data_t make_spi_data(const RobotState& state) {
  spi_data_t message{};
  const JointArray<double> q = sdk_to_wire(state.q);
  const JointArray<double> qd = sdk_to_wire(state.qd);
  const JointArray<double> tau = sdk_to_wire(state.tau);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const std::size_t abad = joint_index(leg, 0), hip = joint_index(leg, 1), knee = joint_index(leg, 2);
    message.q_abad[leg] = static_cast<float>(q[abad]);
    message.q_hip[leg] = static_cast<float>(q[hip]);
    message.q_knee[leg] = static_cast<float>(q[knee]);
    message.qd_abad[leg] = static_cast<float>(qd[abad]);
    message.qd_hip[leg] = static_cast<float>(qd[hip]);
    message.qd_knee[leg] = static_cast<float>(qd[knee]);
    message.tau_abad[leg] = static_cast<float>(tau[abad]);
    message.tau_hip[leg] = static_cast<float>(tau[hip]);
    message.tau_knee[leg] = static_cast<float>(tau[knee]);
    message.tmp_abad[leg] = tenths_of_degree(state.temperature_c[abad]);
    message.tmp_hip[leg] = tenths_of_degree(state.temperature_c[hip]);
    message.tmp_knee[leg] = tenths_of_degree(state.temperature_c[knee]);
  }
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    message.flags[i] = static_cast<std::int32_t>(motor_error_word(state.motor_faults[i], state.driver_mode[i]));
  }
  return message;
}

JointReading joint_state_from_spi_data(const spi_data_t& message) {
  JointReading state;
  JointArray<double> q{}, qd{}, tau{};
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const std::size_t abad = joint_index(leg, 0), hip = joint_index(leg, 1), knee = joint_index(leg, 2);
    q[abad] = message.q_abad[leg];
    q[hip] = message.q_hip[leg];
    q[knee] = message.q_knee[leg];
    qd[abad] = message.qd_abad[leg];
    qd[hip] = message.qd_hip[leg];
    qd[knee] = message.qd_knee[leg];
    tau[abad] = message.tau_abad[leg];
    tau[hip] = message.tau_hip[leg];
    tau[knee] = message.tau_knee[leg];
    state.temperature_c[abad] = message.tmp_abad[leg] / 10.0;
    state.temperature_c[hip] = message.tmp_hip[leg] / 10.0;
    state.temperature_c[knee] = message.tmp_knee[leg] / 10.0;
  }
  state.q = wire_to_sdk(q);
  state.qd = wire_to_sdk(qd);
  state.tau = wire_to_sdk(tau);
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    const auto word = static_cast<std::uint32_t>(message.flags[i]);
    state.motor_faults[i] = motor_faults_from_word(word);
    state.driver_mode[i] = motor_driver_mode_from_word(word);
  }
  return state;
}

motor_ctrl_state_lcmt make_motor_ctrl_state(const MotorSdkStatus& status) {
  motor_ctrl_state_lcmt message{};
  message.err_flag = static_cast<std::int16_t>(status.err_flag);
  message.ctrl_topic_interval = static_cast<float>(status.ctrl_topic_interval_ms);
  return message;
}

}  // namespace cerebellum
