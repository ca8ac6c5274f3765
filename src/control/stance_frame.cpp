#include "control/stance_frame.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {

Eigen::Matrix3d rotation_from_rpy(const Eigen::Vector3d& rpy) {
  return (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Vector3d rotation_error(const Eigen::Matrix3d& desired, const Eigen::Matrix3d& actual) {
  const Eigen::AngleAxisd error(desired * actual.transpose());
  return error.angle() * error.axis();
}

std::array<Eigen::Vector3d, kNumLegs> feet_from_com(const RobotState& state, const Eigen::Matrix3d& rotation,
                                                    const Eigen::Vector3d& com_in_body) {
  std::array<Eigen::Vector3d, kNumLegs> feet{};
  const Eigen::Vector3d com = rotation * com_in_body;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) feet[leg] = rotation * state.foot_position_body[leg] - com;
  return feet;
}

double wrap_angle(double angle_rad) { return std::remainder(angle_rad, 2.0 * robot::kPi); }

Eigen::Vector3d StanceFrame::body_rpy(const RobotState& state) const {
  return {state.rpy.x(), state.rpy.y(), wrap_angle(state.rpy.z() - yaw_anchor_rad_)};
}

Eigen::Matrix3d StanceFrame::body_rotation(const RobotState& state) const { return rotation_from_rpy(body_rpy(state)); }

Eigen::Vector3d StanceFrame::angular_velocity(const RobotState& state) const {
  return Eigen::AngleAxisd(-yaw_anchor_rad_, Eigen::Vector3d::UnitZ()) * state.omega_world;
}

void StanceFrame::anchor(const RobotState& state) {
  yaw_anchor_rad_ = state.rpy.z();
  const Eigen::Matrix3d rotation = body_rotation(state);
  // feet relative to the body origin, level axes
  std::array<Eigen::Vector3d, kNumLegs> feet{};
  double ground_z = 0.0;
  int contacts = 0;
  double lowest_z = 0.0;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    feet[leg] = rotation * state.foot_position_body[leg];
    lowest_z = std::min(lowest_z, feet[leg].z());
    if (state.contact[leg] > 0.5) {
      ground_z += feet[leg].z();
      ++contacts;
    }
  }
  ground_z = contacts > 0 ? ground_z / contacts : lowest_z;
  // ground plane through the foot centres' contact points
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (const Eigen::Vector3d& foot : feet) centroid += foot.head<2>() / static_cast<double>(kNumLegs);
  const Eigen::Vector3d body_origin(-centroid.x(), -centroid.y(), -ground_z + robot::kFootRadius);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    footholds_[leg] = body_origin + feet[leg];
    if (state.contact[leg] <= 0.5 && contacts > 0) footholds_[leg].z() = robot::kFootRadius;
  }
  anchored_pose_.rpy = body_rpy(state);
  anchored_pose_.position = body_origin;
}

bool StanceFrame::estimate(const RobotState& state, const LegMask& feet, Eigen::Vector3d& position,
                           Eigen::Vector3d& velocity) const {
  const Eigen::Matrix3d rotation = body_rotation(state);
  const Eigen::Vector3d omega = angular_velocity(state);
  position.setZero();
  velocity.setZero();
  int count = 0;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    if (!feet[leg]) continue;
    const std::size_t j = kJointsPerLeg * leg;
    const Vec3 q(state.q[j], state.q[j + 1], state.q[j + 2]);
    const Vec3 qd(state.qd[j], state.qd[j + 1], state.qd[j + 2]);
    const Eigen::Vector3d foot = rotation * state.foot_position_body[leg];
    // the foot stands still: 0 = v_body + omega x foot + R J qd
    position += footholds_[leg] - foot;
    velocity += -omega.cross(foot) - rotation * (foot_jacobian(leg, q) * qd);
    ++count;
  }
  if (count == 0) return false;
  position /= count;
  velocity /= count;
  return true;
}

Eigen::Vector3d StanceFrame::centroid(const LegMask& feet) const {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    if (!feet[leg]) continue;
    sum += footholds_[leg];
    ++count;
  }
  return count > 0 ? Eigen::Vector3d(sum / count) : sum;
}

}  // namespace cerebellum
