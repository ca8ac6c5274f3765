#include "io/udp_aliengo/aliengo_wire.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"
#include "unitree_legged_sdk/comm.h"

namespace cerebellum {
namespace sdk = UNITREE_LEGGED_SDK;
namespace {

static_assert(sizeof(sdk::HighCmd) == kHighCmdBytes && sizeof(sdk::HighState) == kHighStateBytes);

bool finite(const float* values, std::size_t n) {
  return std::all_of(values, values + n, [](float v) { return std::isfinite(v); });
}

void put3(float (&out)[3], const Eigen::Vector3d& v) {
  for (int i = 0; i < 3; ++i) out[i] = static_cast<float>(v[i]);
}
void put(sdk::Cartesian& out, const Eigen::Vector3d& v) {
  out.x = static_cast<float>(v.x());
  out.y = static_cast<float>(v.y());
  out.z = static_cast<float>(v.z());
}
Eigen::Vector3d get(const sdk::Cartesian& c) { return {c.x, c.y, c.z}; }

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
  sdk::HighCmd cmd;
  std::memcpy(&cmd, data, sizeof cmd);
  if (cmd.levelFlag != sdk::HIGHLEVEL && cmd.levelFlag != sdk::TRIGERLEVEL) return AlienGoDecode::LowLevel;
  if (!finite(&cmd.dFootRaiseHeight, 1) || !finite(&cmd.dBodyHeight, 1) || !finite(cmd.position, 2) ||
      !finite(cmd.rpy, 3) || !finite(cmd.velocity, 2) || !finite(&cmd.yawSpeed, 1)) {
    return AlienGoDecode::NonFinite;
  }
  out.mode = cmd.mode;
  out.gait_type = cmd.gaitType;
  out.speed_level = cmd.speedLevel;
  out.foot_raise_m = cmd.dFootRaiseHeight;
  out.body_height_m = cmd.dBodyHeight;
  std::copy(cmd.position, cmd.position + 2, out.position.begin());
  std::copy(cmd.rpy, cmd.rpy + 3, out.rpy.begin());
  std::copy(cmd.velocity, cmd.velocity + 2, out.velocity.begin());
  out.yaw_speed = cmd.yawSpeed;
  return AlienGoDecode::Ok;
}

void encode_high_cmd(const AlienGoCommand& command, std::uint8_t (&out)[kHighCmdBytes]) {
  sdk::HighCmd cmd{};
  cmd.levelFlag = sdk::HIGHLEVEL;
  cmd.mode = static_cast<std::uint8_t>(command.mode);
  cmd.gaitType = static_cast<std::uint8_t>(command.gait_type);
  cmd.speedLevel = static_cast<std::uint8_t>(command.speed_level);
  cmd.dFootRaiseHeight = command.foot_raise_m;
  cmd.dBodyHeight = command.body_height_m;
  std::copy(command.position.begin(), command.position.end(), cmd.position);
  std::copy(command.rpy.begin(), command.rpy.end(), cmd.rpy);
  std::copy(command.velocity.begin(), command.velocity.end(), cmd.velocity);
  cmd.yawSpeed = command.yaw_speed;
  sdk::store_crc(&cmd, sizeof cmd);
  std::memcpy(out, &cmd, sizeof cmd);
}

AlienGoFeedback make_feedback(const RobotState& state, int mode) {
  AlienGoFeedback f;
  f.mode = mode;
  f.quaternion_wxyz = {state.orientation.w(), state.orientation.x(), state.orientation.y(), state.orientation.z()};
  f.gyroscope = state.omega_body;
  // an accelerometer measures the specific force: acceleration minus gravity, in the body frame
  const Eigen::Matrix3d world_to_body = state.orientation.toRotationMatrix().transpose();
  f.accelerometer = world_to_body * (state.accel_world + Eigen::Vector3d(0.0, 0.0, robot::kGravityMPerS2));
  f.rpy = state.rpy;
  // the simulated IMU has no thermal model: the coolest motor, the body's inside temperature
  f.temperature_c =
      static_cast<int>(std::lround(*std::min_element(state.temperature_c.begin(), state.temperature_c.end())));
  f.position = state.position_world;
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
  sdk::HighState s{};
  s.levelFlag = sdk::HIGHLEVEL;
  s.mode = static_cast<std::uint8_t>(f.mode);
  for (int i = 0; i < 4; ++i) s.imu.quaternion[i] = static_cast<float>(f.quaternion_wxyz[i]);
  put3(s.imu.gyroscope, f.gyroscope);
  put3(s.imu.accelerometer, f.accelerometer);
  put3(s.imu.rpy, f.rpy);
  s.imu.temperature = static_cast<std::int8_t>(std::clamp(f.temperature_c, -128, 127));
  put3(s.position, f.position);
  put3(s.velocity, f.velocity);
  s.yawSpeed = static_cast<float>(f.yaw_speed);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    put(s.footPosition2Body[leg], f.foot_position[leg]);
    put(s.footSpeed2Body[leg], f.foot_velocity[leg]);
    s.footForce[leg] = static_cast<std::int16_t>(std::clamp(f.foot_force[leg], -32768, 32767));
  }
  sdk::store_crc(&s, sizeof s);
  std::memcpy(out, &s, sizeof s);
}

bool decode_high_state(const std::uint8_t* data, std::size_t size, AlienGoFeedback& f) {
  if (data == nullptr || size != kHighStateBytes) return false;
  if (sdk::stored_crc(data, size) != sdk::frame_crc(data, size)) return false;
  sdk::HighState s;
  std::memcpy(&s, data, sizeof s);
  f.mode = s.mode;
  for (int i = 0; i < 4; ++i) f.quaternion_wxyz[i] = s.imu.quaternion[i];
  f.gyroscope = {s.imu.gyroscope[0], s.imu.gyroscope[1], s.imu.gyroscope[2]};
  f.accelerometer = {s.imu.accelerometer[0], s.imu.accelerometer[1], s.imu.accelerometer[2]};
  f.rpy = {s.imu.rpy[0], s.imu.rpy[1], s.imu.rpy[2]};
  f.temperature_c = s.imu.temperature;
  f.position = {s.position[0], s.position[1], s.position[2]};
  f.velocity = {s.velocity[0], s.velocity[1], s.velocity[2]};
  f.yaw_speed = s.yawSpeed;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    f.foot_position[leg] = get(s.footPosition2Body[leg]);
    f.foot_velocity[leg] = get(s.footSpeed2Body[leg]);
    f.foot_force[leg] = s.footForce[leg];
  }
  return true;
}

}  // namespace cerebellum
