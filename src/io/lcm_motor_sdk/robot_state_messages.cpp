#include "io/lcm_motor_sdk/robot_state_messages.hpp"

#include <cmath>

#include "core/leg_kinematics.hpp"
#include "io/wire_floats.hpp"

namespace cerebellum {
namespace {

Vec3 leg_slice(const JointArray<double>& values, std::size_t leg) {
  return {values[joint_index(leg, 0)], values[joint_index(leg, 1)], values[joint_index(leg, 2)]};
}

}  // namespace

state_estimator_lcmt make_state_estimator(const RobotState& state) {
  state_estimator_lcmt message{};
  put_vector3(message.p, state.position_world);
  put_vector3(message.vWorld, state.velocity_world);
  put_vector3(message.vBody, state.velocity_body);
  put_vector3(message.p_abs, state.position_world);
  put_vector3(message.vWorld_abs, state.velocity_world);
  put_vector3(message.vBody_abs, state.velocity_body);
  put_vector3(message.rpy, state.rpy);
  put_vector3(message.omegaBody, state.omega_body);
  put_vector3(message.omegaWorld, state.omega_world);
  message.quat[0] = static_cast<float>(state.orientation.w());
  message.quat[1] = static_cast<float>(state.orientation.x());
  message.quat[2] = static_cast<float>(state.orientation.y());
  message.quat[3] = static_cast<float>(state.orientation.z());
  // the IMU's specific force as the vendor's estimator publishes it: aBody the accelerometer
  // (body frame), aWorld the same turned into the world; +9.81 on z at rest, gravity included
  put_vector3(message.aBody, state.specific_force_body);
  put_vector3(message.aWorld, state.orientation * state.specific_force_body);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg)
    message.contactEstimate[leg] = static_cast<float>(state.contact[leg]);
  message.timestamp = static_cast<std::int64_t>(std::llround(state.time_s * 1e9));
  return message;
}

ImuReading imu_from_state_estimator(const state_estimator_lcmt& message) {
  ImuReading imu;
  for (std::size_t i = 0; i < 4; ++i) imu.quat[i] = message.quat[i];
  for (std::size_t i = 0; i < 3; ++i) {
    imu.gyro_rad_s[i] = message.omegaBody[i];
    imu.specific_force_m_s2[i] = message.aBody[i];
  }
  return imu;
}

leg_control_data_lcmt make_leg_control_data(const RobotState& state, const JointCommand& command) {
  leg_control_data_lcmt message{};
  const JointArray<double> q = sdk_to_wire(state.q);
  const JointArray<double> qd = sdk_to_wire(state.qd);
  const JointArray<double> tau = sdk_to_wire(state.tau);
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    message.q[i] = static_cast<float>(q[i]);
    message.qd[i] = static_cast<float>(qd[i]);
    message.tau_est[i] = static_cast<float>(tau[i]);
  }
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Vec3 q_leg = leg_slice(state.q, leg);
    const Mat3 jacobian = foot_jacobian(leg, q_leg);
    put_vector3(&message.p[3 * leg], foot_position_in_hip(leg, q_leg));
    put_vector3(&message.v[3 * leg], jacobian * leg_slice(state.qd, leg));
    put_vector3(&message.force_est[3 * leg], foot_force_from_torque(jacobian, leg_slice(state.tau, leg)));
    put_vector3(&message.force_desired[3 * leg], foot_force_from_torque(jacobian, leg_slice(command.tau_ff, leg)));
  }
  return message;
}

}  // namespace cerebellum
