// The stance frame of a standing robot: level, turned like the body was when the stand began,
// origin on the ground at the centroid of the footholds. Standing controllers express the body
// pose in it and estimate the pose from the feet that stand still on the ground.
#pragma once

#include <array>

#include <Eigen/Core>

#include "core/robot_state.hpp"

namespace cerebellum {

// roll, pitch, yaw (ZYX) and the body origin, in the stance frame
struct BodyPose {
  Eigen::Vector3d rpy = Eigen::Vector3d::Zero();
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

// rotation from ZYX angles: Rz(yaw) Ry(pitch) Rx(roll)
Eigen::Matrix3d rotation_from_rpy(const Eigen::Vector3d& rpy);
// the rotation that takes `actual` to `desired` as axis times angle (world axes): an attitude error
Eigen::Vector3d rotation_error(const Eigen::Matrix3d& desired, const Eigen::Matrix3d& actual);
// each foot's position relative to the centre of mass, level axes (rotation: body to level)
std::array<Eigen::Vector3d, kNumLegs> feet_from_com(const RobotState& state, const Eigen::Matrix3d& rotation,
                                                    const Eigen::Vector3d& com_in_body);
// angle wrapped to (-pi, pi]
double wrap_angle(double angle_rad);

using LegMask = std::array<bool, kNumLegs>;
inline constexpr LegMask kAllLegs{true, true, true, true};

class StanceFrame {
 public:
  // anchor the frame at the robot's current feet; feet out of contact are projected onto the
  // ground plane of the others
  void anchor(const RobotState& state);

  // body orientation in this frame (yaw relative to the anchor yaw)
  Eigen::Vector3d body_rpy(const RobotState& state) const;
  // body-to-stance rotation
  Eigen::Matrix3d body_rotation(const RobotState& state) const;
  // angular velocity in this frame
  Eigen::Vector3d angular_velocity(const RobotState& state) const;

  // body origin position and velocity from the legs in `feet` (their footholds held fixed);
  // false when no leg is given
  bool estimate(const RobotState& state, const LegMask& feet, Eigen::Vector3d& position,
                Eigen::Vector3d& velocity) const;

  const Eigen::Vector3d& foothold(std::size_t leg) const { return footholds_[leg]; }
  // the foothold of a leg that has just been put down: its foot as seen from the body pose
  void set_foothold(std::size_t leg, const Eigen::Vector3d& position) { footholds_[leg] = position; }
  // centroid of the footholds in `feet` (stance frame; z on the ground)
  Eigen::Vector3d centroid(const LegMask& feet) const;
  // the body pose the robot had when anchored
  const BodyPose& anchored_pose() const { return anchored_pose_; }

 private:
  double yaw_anchor_rad_ = 0.0;
  std::array<Eigen::Vector3d, kNumLegs> footholds_{};
  BodyPose anchored_pose_;
};

}  // namespace cerebellum
