// The two-leg stand's balance, designed on the robot's own MuJoCo model: a family of upright
// equilibria on the hind feet, from a crouch (trunk nose up a little, centre of mass over the hind
// feet, front feet just off the ground) to the trunk near vertical with the front legs folded,
// and for each an LQR gain on the model linearised there (contacts included). Balancing on two
// point feet is underactuated (no ankle): the hips and knees move the body so that the centre of
// mass stays over the feet, which a gain on the whole body's state does where hand-built
// reduced models (a centroidal or an acrobot LQR) could not bring the rise (docs/motions.md).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace cerebellum {

// MuJoCo's coordinates of the floating robot: position (3), quaternion w x y z (4), 12 joints
inline constexpr int kUprightPositionSize = 19;
// velocities and position differences: linear (world), angular (body), 12 joints
inline constexpr int kUprightVelocitySize = 18;
inline constexpr int kUprightStateSize = 2 * kUprightVelocitySize;

using UprightPosition = Eigen::Matrix<double, kUprightPositionSize, 1>;
using UprightVelocity = Eigen::Matrix<double, kUprightVelocitySize, 1>;
using UprightStateError = Eigen::Matrix<double, kUprightStateSize, 1>;
using UprightGain = Eigen::Matrix<double, kNumJoints, kUprightStateSize>;

struct UprightDesignConfig {
  // the family, from the crouch (s = 0) to the upright pose (s = 1): the trunk's elevation (nose
  // up) and the hind hip joints' height above the ground
  double start_elevation_rad = 0.2;
  double end_elevation_rad = 1.4;
  double start_hip_height_m = 0.14;
  double end_hip_height_m = 0.18;
  // s = 0: the front feet this far above the ground, this far ahead of the hind feet (the stand's)
  double front_lift_m = 0.03;
  double front_foot_ahead_m = 0.328;
  // s = 1: the front legs folded (hip, knee; SDK convention)
  double folded_front_hip_rad = -0.3;
  double folded_front_knee_rad = -2.3;
  int samples = 12;
  // LQR weights: roll and pitch in the world (the yaw about the vertical and the position are
  // neutral: friction holds the feet), joint angles, trunk and joint velocities; torques (per Nm^2)
  double tilt_weight = 300.0;
  double joint_weight = 60.0;
  double trunk_velocity_weight = 1.0;
  double joint_velocity_weight = 0.1;
  double torque_weight = 3.0;
};

struct UprightSample {
  double elevation_rad = 0.0;
  // heading frame, x forward, origin on the ground under the hind feet's midpoint at s = 0; the
  // feet roll along the family (their contact points stay, their centres move with the shanks)
  UprightPosition position;
  Eigen::Vector3d hind_feet_mid_m;  // the hind foot centres' midpoint
  double rolling_origin_rad = 0.0;  // the shanks' roll angle at s = 0 (upright_state)
  JointArray<double> torque_nm{};   // the joint torques that hold it
  UprightGain gain;                 // torque = torque_nm - gain * state error
};

// throws std::runtime_error naming the model file, or the sample without an equilibrium
std::vector<UprightSample> design_upright_balance(const std::string& model_path, const UprightDesignConfig& config,
                                                  double control_period_s);

}  // namespace cerebellum
