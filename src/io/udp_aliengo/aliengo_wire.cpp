#include "io/udp_aliengo/aliengo_wire.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>

#include "core/leg_kinematics.hpp"
#include "unitree_legged_sdk/comm.h"

namespace cerebellum {
namespace sdk = UNITREE_LEGGED_SDK;
namespace {

static_assert(sizeof(sdk::HighCmd) == kHighCmdBytes && sizeof(sdk::HighState) == kHighStateBytes);

// fields are read and written by their offsets in the packed structs (comm.h), never through a
// pointer or reference into them: a float inside a packed struct is not 4-byte aligned
float get_f32(const std::uint8_t* frame, std::size_t offset) {
  float v;
  std::memcpy(&v, frame + offset, sizeof v);
  return v;
}
void put_f32(std::uint8_t* frame, std::size_t offset, double value) {
  const auto v = static_cast<float>(value);
  std::memcpy(frame + offset, &v, sizeof v);
}
void put_vec(std::uint8_t* frame, std::size_t offset, const Eigen::Vector3d& v) {
  for (int i = 0; i < 3; ++i) put_f32(frame, offset + 4 * static_cast<std::size_t>(i), v[i]);
}
Eigen::Vector3d get_vec(const std::uint8_t* frame, std::size_t offset) {
  return {get_f32(frame, offset), get_f32(frame, offset + 4), get_f32(frame, offset + 8)};
}

constexpr std::size_t kCmdFloatsBegin = offsetof(sdk::HighCmd, dFootRaiseHeight);
constexpr std::size_t kCmdFloatsEnd = offsetof(sdk::HighCmd, led);  // dFootRaiseHeight .. yawSpeed
constexpr std::size_t kImu = offsetof(sdk::HighState, imu);
constexpr std::size_t kImuQuaternion = kImu + offsetof(sdk::IMU, quaternion);
constexpr std::size_t kImuGyroscope = kImu + offsetof(sdk::IMU, gyroscope);
constexpr std::size_t kImuAccelerometer = kImu + offsetof(sdk::IMU, accelerometer);
constexpr std::size_t kImuRpy = kImu + offsetof(sdk::IMU, rpy);
constexpr std::size_t kImuTemperature = kImu + offsetof(sdk::IMU, temperature);
constexpr std::size_t kCartesianBytes = sizeof(sdk::Cartesian);

}  // namespace

const char* to_string(AlienGoDecode result) {
  switch (result) {
    case AlienGoDecode::Ok: return "ok";
    case AlienGoDecode::WrongLength: return "wrong length";
    case AlienGoDecode::BadCrc: return "bad CRC";
    case AlienGoDecode::LowLevel: return "not a high-level frame (levelFlag)";
    case AlienGoDecode::NonFinite: return "NaN/Inf in a field";
  }
  return "?";
}

AlienGoDecode decode_high_cmd(const std::uint8_t* data, std::size_t size, AlienGoCommand& out) {
  if (data == nullptr || size != kHighCmdBytes) return AlienGoDecode::WrongLength;
  if (sdk::stored_crc(data, size) != sdk::frame_crc(data, size)) return AlienGoDecode::BadCrc;
  const std::uint8_t level = data[offsetof(sdk::HighCmd, levelFlag)];
  if (level != sdk::HIGHLEVEL && level != sdk::TRIGERLEVEL) return AlienGoDecode::LowLevel;
  for (std::size_t offset = kCmdFloatsBegin; offset < kCmdFloatsEnd; offset += 4) {
    if (!std::isfinite(get_f32(data, offset))) return AlienGoDecode::NonFinite;
  }
  out.mode = data[offsetof(sdk::HighCmd, mode)];
  out.gait_type = data[offsetof(sdk::HighCmd, gaitType)];
  out.speed_level = data[offsetof(sdk::HighCmd, speedLevel)];
  out.foot_raise_m = get_f32(data, offsetof(sdk::HighCmd, dFootRaiseHeight));
  out.body_height_m = get_f32(data, offsetof(sdk::HighCmd, dBodyHeight));
  for (std::size_t i = 0; i < 2; ++i) out.position[i] = get_f32(data, offsetof(sdk::HighCmd, position) + 4 * i);
  for (std::size_t i = 0; i < 3; ++i) out.rpy[i] = get_f32(data, offsetof(sdk::HighCmd, rpy) + 4 * i);
  for (std::size_t i = 0; i < 2; ++i) out.velocity[i] = get_f32(data, offsetof(sdk::HighCmd, velocity) + 4 * i);
  out.yaw_speed = get_f32(data, offsetof(sdk::HighCmd, yawSpeed));
  return AlienGoDecode::Ok;
}

void encode_high_cmd(const AlienGoCommand& command, std::uint8_t (&out)[kHighCmdBytes]) {
  std::memset(out, 0, sizeof out);
  out[offsetof(sdk::HighCmd, levelFlag)] = sdk::HIGHLEVEL;
  out[offsetof(sdk::HighCmd, mode)] = static_cast<std::uint8_t>(command.mode);
  out[offsetof(sdk::HighCmd, gaitType)] = static_cast<std::uint8_t>(command.gait_type);
  out[offsetof(sdk::HighCmd, speedLevel)] = static_cast<std::uint8_t>(command.speed_level);
  put_f32(out, offsetof(sdk::HighCmd, dFootRaiseHeight), command.foot_raise_m);
  put_f32(out, offsetof(sdk::HighCmd, dBodyHeight), command.body_height_m);
  for (std::size_t i = 0; i < 2; ++i) put_f32(out, offsetof(sdk::HighCmd, position) + 4 * i, command.position[i]);
  for (std::size_t i = 0; i < 3; ++i) put_f32(out, offsetof(sdk::HighCmd, rpy) + 4 * i, command.rpy[i]);
  for (std::size_t i = 0; i < 2; ++i) put_f32(out, offsetof(sdk::HighCmd, velocity) + 4 * i, command.velocity[i]);
  put_f32(out, offsetof(sdk::HighCmd, yawSpeed), command.yaw_speed);
  sdk::store_crc(out, sizeof out);
}

AlienGoFeedback make_feedback(const RobotState& state, int mode, const SportFrame& frame) {
  AlienGoFeedback f;
  f.mode = mode;
  f.quaternion_wxyz = {state.orientation.w(), state.orientation.x(), state.orientation.y(), state.orientation.z()};
  f.gyroscope = state.omega_body;
  // the accelerometer as it reads: the specific force (gravity included), body frame
  f.accelerometer = state.specific_force_body;
  f.rpy = state.rpy;
  // the IMU's own sensor; an unreadable one reads 0 (the wire's i8 has no "unknown")
  const double imu_c = state.imu_temperature_c;
  f.temperature_c = std::isfinite(imu_c) ? static_cast<int>(std::lround(std::clamp(imu_c, -128.0, 127.0))) : 0;
  // the odometry (it drifts, as on the robot) in the sport frame: from its origin, turned by its yaw
  const Eigen::Vector3d from_origin =
      state.position_world - Eigen::Vector3d(frame.origin[0], frame.origin[1], frame.origin[2]);
  const double c = std::cos(frame.yaw_rad), s = std::sin(frame.yaw_rad);
  f.position = Eigen::Vector3d(c * from_origin.x() + s * from_origin.y(), -s * from_origin.x() + c * from_origin.y(),
                               from_origin.z());
  f.velocity = state.velocity_body;
  f.yaw_speed = state.omega_world.z();
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Eigen::Vector3d q(state.q[3 * leg], state.q[3 * leg + 1], state.q[3 * leg + 2]);
    const Eigen::Vector3d qd(state.qd[3 * leg], state.qd[3 * leg + 1], state.qd[3 * leg + 2]);
    const Eigen::Vector3d tau(state.tau[3 * leg], state.tau[3 * leg + 1], state.tau[3 * leg + 2]);
    const Eigen::Matrix3d jacobian = foot_jacobian(leg, q);
    f.foot_position[leg] = state.foot_position_body[leg];
    f.foot_velocity[leg] = jacobian * qd;
    // the ground's push on the foot (tau = -J^T f), its component along the body's z, in 0.1 N
    const double push_n = -foot_force_from_torque(jacobian, tau).z();
    f.foot_force[leg] = static_cast<int>(std::lround(std::clamp(push_n * 10.0, 0.0, 32767.0)));
  }
  return f;
}

void encode_high_state(const AlienGoFeedback& f, std::uint8_t (&out)[kHighStateBytes]) {
  std::memset(out, 0, sizeof out);
  out[offsetof(sdk::HighState, levelFlag)] = sdk::HIGHLEVEL;
  out[offsetof(sdk::HighState, mode)] = static_cast<std::uint8_t>(f.mode);
  for (std::size_t i = 0; i < 4; ++i) put_f32(out, kImuQuaternion + 4 * i, f.quaternion_wxyz[static_cast<int>(i)]);
  put_vec(out, kImuGyroscope, f.gyroscope);
  put_vec(out, kImuAccelerometer, f.accelerometer);
  put_vec(out, kImuRpy, f.rpy);
  out[kImuTemperature] = static_cast<std::uint8_t>(static_cast<std::int8_t>(std::clamp(f.temperature_c, -128, 127)));
  put_vec(out, offsetof(sdk::HighState, position), f.position);
  put_vec(out, offsetof(sdk::HighState, velocity), f.velocity);
  put_f32(out, offsetof(sdk::HighState, yawSpeed), f.yaw_speed);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    put_vec(out, offsetof(sdk::HighState, footPosition2Body) + kCartesianBytes * leg, f.foot_position[leg]);
    put_vec(out, offsetof(sdk::HighState, footSpeed2Body) + kCartesianBytes * leg, f.foot_velocity[leg]);
    const auto force = static_cast<std::int16_t>(std::clamp(f.foot_force[leg], -32768, 32767));
    std::memcpy(out + offsetof(sdk::HighState, footForce) + 2 * leg, &force, sizeof force);
  }
  sdk::store_crc(out, sizeof out);
}

bool decode_high_state(const std::uint8_t* data, std::size_t size, AlienGoFeedback& f) {
  if (data == nullptr || size != kHighStateBytes) return false;
  if (sdk::stored_crc(data, size) != sdk::frame_crc(data, size)) return false;
  f.mode = data[offsetof(sdk::HighState, mode)];
  for (std::size_t i = 0; i < 4; ++i) f.quaternion_wxyz[static_cast<int>(i)] = get_f32(data, kImuQuaternion + 4 * i);
  f.gyroscope = get_vec(data, kImuGyroscope);
  f.accelerometer = get_vec(data, kImuAccelerometer);
  f.rpy = get_vec(data, kImuRpy);
  f.temperature_c = static_cast<std::int8_t>(data[kImuTemperature]);
  f.position = get_vec(data, offsetof(sdk::HighState, position));
  f.velocity = get_vec(data, offsetof(sdk::HighState, velocity));
  f.yaw_speed = get_f32(data, offsetof(sdk::HighState, yawSpeed));
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    f.foot_position[leg] = get_vec(data, offsetof(sdk::HighState, footPosition2Body) + kCartesianBytes * leg);
    f.foot_velocity[leg] = get_vec(data, offsetof(sdk::HighState, footSpeed2Body) + kCartesianBytes * leg);
    std::int16_t force;
    std::memcpy(&force, data + offsetof(sdk::HighState, footForce) + 2 * leg, sizeof force);
    f.foot_force[leg] = force;
  }
  return true;
}

}  // namespace cerebellum
