// The robot's state in the coordinates of the two-leg stand's design (upright_balance_design):
// MuJoCo's floating-body coordinates in the heading frame (the yaw at the start removed), with the
// origin on the ground under the hind feet. The trunk's position comes from the hind legs'
// kinematics (the feet are where it stands), not from the estimator's drifting position.
#pragma once

#include <Eigen/Geometry>

#include "control/upright/upright_balance_design.hpp"
#include "core/robot_state.hpp"

namespace cerebellum {

struct UprightState {
  UprightPosition position;
  UprightVelocity velocity;  // linear (heading frame), angular (body), joints
};

// the hind shanks' mean turn about the world's lateral axis (rad): a spherical foot that rolls
// without slipping moves its centre forward by its radius times the change of this angle
double hind_shank_roll_angle(const Eigen::Matrix3d& trunk_to_world, const JointArray<double>& q);

// feet_height_m: the hind foot centres' height; rolling_origin_rad: the shanks' roll angle at which
// the foot centres are at the design's origin (x = 0)
UprightState upright_state(const RobotState& state, double heading_yaw_rad, double rolling_origin_rad,
                           double feet_height_m);

// to - from in the tangent space: position difference, the rotation from `from` to `to` as axis
// times angle in from's body axes, joint differences (what MuJoCo's mj_differentiatePos gives)
UprightVelocity upright_difference(const UprightPosition& from, const UprightPosition& to);

// the trunk orientation of a position (w x y z at 3..6)
Eigen::Quaterniond upright_orientation(const UprightPosition& position);

}  // namespace cerebellum
