#include "estimation/kinematic_estimator.hpp"

#include <cmath>

#include "core/leg_kinematics.hpp"
#include "core/orientation.hpp"
#include "core/robot_model.hpp"
#include "core/specific_force.hpp"

namespace cerebellum {
namespace {

template <typename Array>
bool all_finite(const Array& values) {
  for (double v : values) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

}  // namespace

bool sensor_frame_is_finite(const SensorFrame& frame) {
  return std::isfinite(frame.time_s) && all_finite(frame.q) && all_finite(frame.qd) && all_finite(frame.tau) &&
         all_finite(frame.imu_quat) && all_finite(frame.imu_gyro) && all_finite(frame.imu_accel);
}

KinematicEstimator::KinematicEstimator(const KinematicEstimatorConfig& config) : config_(config) {}

void KinematicEstimator::reset() {}

void KinematicEstimator::update(const SensorFrame& frame, const ContactPlan& /*plan*/, RobotState& state) {
  state.time_s = frame.time_s;
  // what the drivers and the battery report reaches the safety stage even when the sensors fail
  state.motor_faults = frame.motor_faults;
  state.driver_mode = frame.driver_mode;
  state.battery = frame.battery;
  if (!sensor_frame_is_finite(frame)) {
    state.valid = false;
    return;
  }
  state.q = frame.q;
  state.qd = frame.qd;
  state.tau = frame.tau;
  state.temperature_c = frame.temperature_c;
  state.imu_temperature_c = frame.imu_temperature_c;

  // orientation straight from the IMU's attitude solution
  Eigen::Quaterniond orientation(frame.imu_quat[0], frame.imu_quat[1], frame.imu_quat[2], frame.imu_quat[3]);
  if (orientation.norm() < 0.5) {
    state.valid = false;
    return;
  }
  orientation.normalize();
  state.orientation = orientation;
  state.rpy = rpy_from_quaternion(orientation);
  const Eigen::Matrix3d body_to_world = orientation.toRotationMatrix();
  state.omega_body = Eigen::Vector3d(frame.imu_gyro[0], frame.imu_gyro[1], frame.imu_gyro[2]);
  state.omega_world = body_to_world * state.omega_body;
  // the accelerometer as it reads (what the interfaces publish), and the acceleration it means
  state.specific_force_body = Eigen::Vector3d(frame.imu_accel[0], frame.imu_accel[1], frame.imu_accel[2]);
  state.accel_world = acceleration_from_specific_force(body_to_world * state.specific_force_body);

  // feet, contact from the foot force J^-T tau, height from the feet in contact
  double height_sum = 0.0;
  int feet_in_contact = 0;
  double lowest_foot = 0.0;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Vec3 q(frame.q[3 * leg], frame.q[3 * leg + 1], frame.q[3 * leg + 2]);
    const Vec3 tau(frame.tau[3 * leg], frame.tau[3 * leg + 1], frame.tau[3 * leg + 2]);
    state.foot_position_body[leg] = foot_position_in_body(leg, q);
    const Mat3 jacobian = foot_jacobian(leg, q);
    // statics: motor torque balances the ground's force on the foot, tau = -J^T f (zero when singular)
    const Vec3 ground_reaction = -foot_force_from_torque(jacobian, tau);
    const double force_z = (body_to_world * ground_reaction).z();
    state.contact[leg] = force_z > config_.contact_force_threshold_n ? 1.0 : 0.0;
    const double foot_height = -(body_to_world * state.foot_position_body[leg]).z() + robot::kFootRadius;
    lowest_foot = std::max(lowest_foot, foot_height);
    if (state.contact[leg] > 0.5) {
      height_sum += foot_height;
      ++feet_in_contact;
    }
  }
  state.height_m = feet_in_contact > 0 ? height_sum / feet_in_contact : lowest_foot;
  state.valid = true;
}

}  // namespace cerebellum
