#include "control/leg_gravity.hpp"

#include <array>

#include <Eigen/Geometry>

#include "core/joint_layout.hpp"
#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

// a link's mass (kg) and centre of mass in its joint frame (m)
struct PointMass {
  double mass_kg;
  Eigen::Vector3d com;
};

}  // namespace

namespace {

// each mass of the leg in the body frame, with the joints that move it, and the joint origins
struct Placed {
  double mass_kg;
  Eigen::Vector3d position;
  int moved_by;  // 1: abad only, 2: abad and hip, 3: all three
};
struct PlacedLeg {
  std::array<Placed, kLegPointMasses> masses;
  Eigen::Vector3d o_abad, o_hip, o_knee, axis_pitch;
};

PlacedLeg place_leg(std::size_t leg, const Eigen::Vector3d& q) {
  // the published centres are for a right leg: left legs mirror y
  const double side = leg_side_sign(leg);
  const auto link = [side](double x, double y_right, double z) { return Eigen::Vector3d(x, -side * y_right, z); };
  const auto published = [&link](const robot::LinkMass& l) {
    return PointMass{l.mass_kg, link(l.com_m[0], l.com_m[1], l.com_m[2])};
  };
  const PointMass abad_link = published(robot::kAbadLink);
  const PointMass hip_rotor{robot::kRotorMassKg, link(0.0, -robot::kHipRotorOffsetM, 0.0)};
  const PointMass thigh = published(robot::kThighLink);
  const PointMass knee_rotor{robot::kRotorMassKg, {0.0, 0.0, -robot::kKneeRotorOffsetM}};
  const PointMass shank = published(robot::kShankLink);

  // joint frames in the body frame
  const Eigen::Matrix3d r_abad = Eigen::AngleAxisd(q.x(), Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Matrix3d r_thigh = r_abad * Eigen::AngleAxisd(q.y(), Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Matrix3d r_shank = r_thigh * Eigen::AngleAxisd(q.z(), Eigen::Vector3d::UnitY()).toRotationMatrix();
  PlacedLeg placed;
  placed.o_abad = hip_position(leg);
  placed.o_hip = placed.o_abad + r_abad * Eigen::Vector3d(0.0, side * robot::kAbadLength, 0.0);
  placed.o_knee = placed.o_hip + r_thigh * Eigen::Vector3d(0.0, 0.0, -robot::kThighLength);
  placed.axis_pitch = r_abad * Eigen::Vector3d::UnitY();  // hip and knee
  placed.masses = {{
      {abad_link.mass_kg, placed.o_abad + r_abad * abad_link.com, 1},
      {hip_rotor.mass_kg, placed.o_abad + r_abad * hip_rotor.com, 1},
      {thigh.mass_kg, placed.o_hip + r_thigh * thigh.com, 2},
      {knee_rotor.mass_kg, placed.o_hip + r_thigh * knee_rotor.com, 2},
      {shank.mass_kg, placed.o_knee + r_shank * shank.com, 3},
  }};
  return placed;
}

}  // namespace

std::array<LegPointMass, kLegPointMasses> leg_point_masses(std::size_t leg, const Eigen::Vector3d& q) {
  const PlacedLeg placed = place_leg(leg, q);
  std::array<LegPointMass, kLegPointMasses> masses{};
  for (std::size_t i = 0; i < kLegPointMasses; ++i) masses[i] = {placed.masses[i].mass_kg, placed.masses[i].position};
  return masses;
}

Eigen::Vector3d whole_body_com_in_body(const std::array<double, 3>& leg_q) {
  const robot::LinkMass& trunk = robot::kBodyLink;
  double mass = trunk.mass_kg;
  Eigen::Vector3d moment = trunk.mass_kg * Eigen::Vector3d(trunk.com_m[0], trunk.com_m[1], trunk.com_m[2]);
  const Eigen::Vector3d q(leg_q[0], leg_q[1], leg_q[2]);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Eigen::Vector3d hip = hip_position(leg);
    const Eigen::Vector3d abad_rotor(hip.x() > 0.0 ? robot::kAbadRotorX : -robot::kAbadRotorX, hip.y(), hip.z());
    mass += robot::kRotorMassKg;
    moment += robot::kRotorMassKg * abad_rotor;
    for (const LegPointMass& point : leg_point_masses(leg, q)) {
      mass += point.mass_kg;
      moment += point.mass_kg * point.position;
    }
  }
  return moment / mass;
}

Eigen::Vector3d stand_com_in_body() { return whole_body_com_in_body(robot::kStandPose); }

Eigen::Vector3d leg_gravity_torque(std::size_t leg, const Eigen::Vector3d& q, const Eigen::Vector3d& gravity_body) {
  const PlacedLeg placed = place_leg(leg, q);
  const Eigen::Vector3d axis_abad = Eigen::Vector3d::UnitX();
  // holding torque = -(generalised gravity force) = -sum m g . (axis x (p - o))
  Eigen::Vector3d tau = Eigen::Vector3d::Zero();
  for (const Placed& m : placed.masses) {
    const Eigen::Vector3d weight = m.mass_kg * gravity_body;
    tau.x() -= weight.dot(axis_abad.cross(m.position - placed.o_abad));
    if (m.moved_by >= 2) tau.y() -= weight.dot(placed.axis_pitch.cross(m.position - placed.o_hip));
    if (m.moved_by >= 3) tau.z() -= weight.dot(placed.axis_pitch.cross(m.position - placed.o_knee));
  }
  return tau;
}

Eigen::Matrix3d leg_mass_jacobian(std::size_t leg, const Eigen::Vector3d& q) {
  // holding torque for a unit gravity along axis k: -(sum m_i J_i)' e_k, the k-th row negated
  Eigen::Matrix3d map;
  for (int k = 0; k < 3; ++k) map.row(k) = -leg_gravity_torque(leg, q, Eigen::Vector3d::Unit(k)).transpose();
  return map;
}

Eigen::Vector3d ground_force_on_foot_world(const RobotState& state, std::size_t leg) {
  const Eigen::Vector3d gravity_body = state.orientation.conjugate() * Eigen::Vector3d(0.0, 0.0, -robot::kGravityMPerS2);
  const Eigen::Vector3d q = leg_vector(state.q, leg);
  const Eigen::Vector3d tau = leg_vector(state.tau, leg) - leg_gravity_torque(leg, q, gravity_body);
  return state.orientation * -foot_force_from_torque(foot_jacobian(leg, q), tau);
}

}  // namespace cerebellum
