// Joint torques that hold a leg's own links against gravity (the G(q) of the leg as a chain
// fixed to the trunk), from the published link masses and centres of mass
// (robot-cyberdog2.md; right-leg values, y mirrored for left legs; rotors as point masses).
#pragma once

#include <array>
#include <cstddef>

#include <Eigen/Core>

#include "core/robot_state.hpp"

namespace cerebellum {

// q: abad, hip, knee (SDK convention); gravity_body: gravity vector in the body frame (m/s^2)
Eigen::Vector3d leg_gravity_torque(std::size_t leg, const Eigen::Vector3d& q, const Eigen::Vector3d& gravity_body);

// the leg's links and rotors as point masses, centres in the body frame
inline constexpr std::size_t kLegPointMasses = 5;
struct LegPointMass {
  double mass_kg;
  Eigen::Vector3d position;
};
std::array<LegPointMass, kLegPointMasses> leg_point_masses(std::size_t leg, const Eigen::Vector3d& q);

// the whole robot's centre of mass in the body frame (trunk, its abad rotors and the legs) with
// every leg at these joint angles, from the same mass model
Eigen::Vector3d whole_body_com_in_body(const std::array<double, 3>& leg_q);
// ... in the default stand (robot::kStandPose): what the stand and walking controllers balance
Eigen::Vector3d stand_com_in_body();

// sum over the leg's links of mass times the Jacobian of the link's centre of mass (body frame):
// the leg's linear momentum relative to the trunk is this times the joint velocities. Read from
// the gravity torques (they are its transpose applied to g), so the two share one mass model.
Eigen::Matrix3d leg_mass_jacobian(std::size_t leg, const Eigen::Vector3d& q);

// the ground's force on a foot (world, N) from the leg's joint torques beyond its own weight:
// statics (tau = -J^T f), the leg's accelerations not taken out; what a landing or a swing foot
// meeting something is told by
Eigen::Vector3d ground_force_on_foot_world(const RobotState& state, std::size_t leg);

}  // namespace cerebellum
