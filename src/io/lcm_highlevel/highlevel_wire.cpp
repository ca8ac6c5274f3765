#include "io/lcm_highlevel/highlevel_wire.hpp"

#include <cmath>
#include <cstdint>

#include "file_send_lcmt.hpp"
#include "io/common/motor_error_word.hpp"
#include "io/wire_floats.hpp"
#include "motions/user_gait_file.hpp"

namespace cerebellum {
namespace {

constexpr std::size_t kStringLengthBytes = 4;

std::uint64_t read_big_endian(const std::uint8_t* bytes, std::size_t count) {
  std::uint64_t value = 0;
  for (std::size_t i = 0; i < count; ++i) value = (value << 8) | bytes[i];
  return value;
}

template <std::size_t N>
void copy_floats(const float (&from)[N], std::array<float, N>& to) {
  for (std::size_t i = 0; i < N; ++i) to[i] = from[i];
}

template <std::size_t N>
void copy_floats(const std::array<float, N>& from, float (&to)[N]) {
  for (std::size_t i = 0; i < N; ++i) to[i] = from[i];
}

}  // namespace

WireDecode decode_robot_control_cmd(const void* data, std::size_t size, HighLevelCommand& command) {
  robot_control_cmd_lcmt message{};
  if (const WireDecode checked = decode_fixed_size(data, size, message); checked != WireDecode::Ok) return checked;
  command.mode = message.mode;
  command.gait_id = message.gait_id;
  command.contact = message.contact;
  command.life_count = message.life_count;
  copy_floats(message.vel_des, command.vel_des);
  copy_floats(message.rpy_des, command.rpy_des);
  copy_floats(message.pos_des, command.pos_des);
  copy_floats(message.acc_des, command.acc_des);
  copy_floats(message.ctrl_point, command.ctrl_point);
  copy_floats(message.foot_pose, command.foot_pose);
  copy_floats(message.step_height, command.step_height);
  command.value = message.value;
  command.duration = message.duration;
  return WireDecode::Ok;
}

robot_control_cmd_lcmt encode_robot_control_cmd(const HighLevelCommand& command) {
  robot_control_cmd_lcmt message{};
  message.mode = static_cast<std::int8_t>(command.mode);
  message.gait_id = static_cast<std::int8_t>(command.gait_id);
  message.contact = static_cast<std::int8_t>(command.contact);
  message.life_count = static_cast<std::int8_t>(command.life_count);
  copy_floats(command.vel_des, message.vel_des);
  copy_floats(command.rpy_des, message.rpy_des);
  copy_floats(command.pos_des, message.pos_des);
  copy_floats(command.acc_des, message.acc_des);
  copy_floats(command.ctrl_point, message.ctrl_point);
  copy_floats(command.foot_pose, message.foot_pose);
  copy_floats(command.step_height, message.step_height);
  message.value = command.value;
  message.duration = command.duration;
  return message;
}

WireDecode decode_file_send(const void* data, std::size_t size, std::string& text) {
  if (size < kLcmFingerprintBytes) return WireDecode::Truncated;
  if (!has_fingerprint(data, size, file_send_lcmt::getHash())) return WireDecode::WrongFingerprint;
  if (size < kLcmFingerprintBytes + kStringLengthBytes) return WireDecode::Truncated;
  // the int32 length counts the terminating nul
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  const std::uint64_t length = read_big_endian(bytes + kLcmFingerprintBytes, kStringLengthBytes);
  if (length > kMaxUserGaitFileBytes + 1) return WireDecode::Oversized;
  const std::size_t expected = kLcmFingerprintBytes + kStringLengthBytes + length;
  if (length == 0 || size < expected) return WireDecode::Truncated;
  if (size > expected) return WireDecode::Oversized;
  const char* characters = reinterpret_cast<const char*>(bytes + kLcmFingerprintBytes + kStringLengthBytes);
  if (characters[length - 1] != '\0') return WireDecode::Truncated;
  text.assign(characters, length - 1);
  return WireDecode::Ok;
}

robot_control_response_lcmt make_response(const HighLevelStatus& status) {
  robot_control_response_lcmt message{};
  message.mode = static_cast<std::int8_t>(status.mode);
  message.gait_id = static_cast<std::int8_t>(status.gait_id);
  message.contact = static_cast<std::int8_t>(status.contact);
  message.order_process_bar = static_cast<std::int8_t>(status.order_process_bar);
  message.switch_status = static_cast<std::int8_t>(status.switch_status);
  message.ori_error = static_cast<std::int8_t>(status.ori_error);
  message.footpos_error = static_cast<std::int16_t>(status.footpos_error);
  for (std::size_t i = 0; i < status.motor_faults.size(); ++i) {
    message.motor_error[i] = static_cast<std::int32_t>(motor_error_word(status.motor_faults[i], status.driver_mode[i]));
  }
  return message;
}

localization_lcmt make_localization(const RobotState& state) {
  localization_lcmt message{};
  put_vector3(message.xyz, state.position_world);
  put_vector3(message.vxyz, state.velocity_world);
  put_vector3(message.rpy, state.rpy);
  put_vector3(message.omegaBody, state.omega_body);
  put_vector3(message.vBody, state.velocity_body);
  message.timestamp = static_cast<std::int64_t>(std::llround(state.time_s * 1e9));
  return message;
}

danger_states_lcmt make_danger_states(const RobotState& state) {
  danger_states_lcmt message{};
  for (std::size_t i = 0; i < kNumJoints; ++i)
    message.motor_temperature[i] = static_cast<float>(state.temperature_c[i]);
  return message;
}

file_recv_lcmt make_file_result(bool accepted) {
  file_recv_lcmt message{};
  message.result = accepted ? 0 : 1;
  return message;
}

}  // namespace cerebellum
