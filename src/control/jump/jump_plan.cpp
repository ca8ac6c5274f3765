#include "control/jump/jump_plan.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "control/leg_gravity.hpp"
#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

using robot::kGravityMPerS2;

// the legs with the feet below their stand positions, the trunk at this height
std::array<Eigen::Vector3d, kNumLegs> legs_at_height(double height_m) {
  const Eigen::Vector3d stand(robot::kStandPose[0], robot::kStandPose[1], robot::kStandPose[2]);
  std::array<Eigen::Vector3d, kNumLegs> q{};
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    Eigen::Vector3d foot = foot_position_in_body(leg, stand);
    foot.z() = -height_m + robot::kFootRadius;
    q[leg] = inverse_kinematics_in_body(leg, foot).q;
  }
  return q;
}

}  // namespace

double flight_time_s(double vz, double drop_m) {
  const double discriminant = vz * vz + 2.0 * kGravityMPerS2 * drop_m;
  return (vz + std::sqrt(std::max(discriminant, 0.0))) / kGravityMPerS2;
}

Eigen::Vector2d braking_distance(const Eigen::Vector2d& com_horizontal_velocity, const JumpLimits& limits) {
  return com_horizontal_velocity * (com_horizontal_velocity.norm() / (2.0 * limits.landing_braking_m_s2));
}

Eigen::Matrix3d standing_momentum_map(const std::array<Eigen::Vector3d, 4>& leg_q, double mass_kg) {
  Eigen::Matrix3d map = Eigen::Matrix3d::Identity();
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    // the foot stands still: J qd = -v
    map -= leg_mass_jacobian(leg, leg_q[leg]) * foot_jacobian(leg, leg_q[leg]).inverse() / mass_kg;
  }
  return map;
}

Eigen::Vector3d standing_angular_momentum(const std::array<Eigen::Vector3d, 4>& leg_q, const Eigen::Vector3d& v,
                                          double mass_kg) {
  // every point mass's position and velocity; the joint rates that keep the feet still move the
  // masses along a short step of their motion
  constexpr double kStepS = 1e-6;
  double leg_mass = 0.0;
  Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();
  Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();  // about the trunk origin
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Eigen::Vector3d qd = -foot_jacobian(leg, leg_q[leg]).inverse() * v;
    const auto now = leg_point_masses(leg, leg_q[leg]);
    const auto next = leg_point_masses(leg, leg_q[leg] + kStepS * qd);
    for (std::size_t i = 0; i < now.size(); ++i) {
      const Eigen::Vector3d velocity = v + (next[i].position - now[i].position) / kStepS;
      leg_mass += now[i].mass_kg;
      first_moment += now[i].mass_kg * now[i].position;
      angular += now[i].mass_kg * now[i].position.cross(velocity);
      momentum += now[i].mass_kg * velocity;
    }
    // the links also spin: all three about the abad axis, thigh and shank about the pitch axis
    // (link axes taken as the body's: the abad joint stays near zero)
    angular.x() +=
        (robot::kAbadLink.inertia_xx_kg_m2 + robot::kThighLink.inertia_xx_kg_m2 + robot::kShankLink.inertia_xx_kg_m2) *
        qd.x();
    angular.y() += robot::kThighLink.inertia_yy_kg_m2 * qd.y() + robot::kShankLink.inertia_yy_kg_m2 * (qd.y() + qd.z());
  }
  // the trunk: the rest of the mass (the body and the abad rotors, symmetric about its centre) at
  // the body's centre of mass, moving at v
  const Eigen::Vector3d trunk_com(robot::kBodyLink.com_m[0], robot::kBodyLink.com_m[1], robot::kBodyLink.com_m[2]);
  const double trunk_mass = mass_kg - leg_mass;
  first_moment += robot::kBodyLink.mass_kg * trunk_com;
  angular += robot::kBodyLink.mass_kg * trunk_com.cross(v);
  momentum += trunk_mass * v;
  const Eigen::Vector3d com = first_moment / mass_kg;
  // about the centre of mass: L_c = L_o - c x p
  return angular - com.cross(momentum);
}

Eigen::Vector2d planned_displacement(const JumpPlan& plan) {
  return plan.crouch_offset_m + plan.push_stroke_m.head<2>() + plan.flight_travel_m.head<2>() +
         plan.landing_foot_offset_m;
}

namespace {

// the legs at take-off and their momentum map: computed once per plan
struct TakeoffLegs {
  std::array<Eigen::Vector3d, kNumLegs> legs;
  Eigen::Matrix3d momentum;
};
TakeoffLegs takeoff_legs_of(const JumpLimits& limits) {
  TakeoffLegs takeoff{legs_at_height(limits.takeoff_height_m), Eigen::Matrix3d::Identity()};
  takeoff.momentum = standing_momentum_map(takeoff.legs, limits.mass_kg);
  return takeoff;
}

// the fastest vertical take-off (centre of mass) and what limits it: the push's force over the
// stroke (v^2 = 2 s K_zz (F / m - g)) or the legs' extension speed
struct VerticalCap {
  double speed_m_s;
  JumpShortfall limit;
};
VerticalCap vertical_speed_cap(const JumpLimits& limits, const Eigen::Matrix3d& momentum) {
  const double stroke_z = limits.takeoff_height_m - limits.crouch_height_m;
  const double force = std::sqrt(2.0 * stroke_z * momentum(2, 2) *
                                 std::max(limits.max_vertical_force_n / limits.mass_kg - kGravityMPerS2, 0.0));
  if (force < limits.max_takeoff_speed_m_s) return {force, kJumpForceLimited};
  return {limits.max_takeoff_speed_m_s, kJumpSpeedLimited};
}

// every figure that follows from the centre of mass's take-off velocity
void finish_plan(JumpPlan& plan, const Eigen::Vector3d& com_velocity, double drop_m, const JumpLimits& limits,
                 const TakeoffLegs& takeoff) {
  const std::array<Eigen::Vector3d, kNumLegs>& takeoff_legs = takeoff.legs;
  const Eigen::Matrix3d& momentum = takeoff.momentum;
  plan.crouch_height_m = limits.crouch_height_m;
  plan.takeoff_height_m = limits.takeoff_height_m;
  plan.momentum_map = momentum;
  plan.com_takeoff_velocity_m_s = com_velocity;
  plan.takeoff_velocity_m_s = momentum.inverse() * com_velocity;
  const double stroke_z = limits.takeoff_height_m - limits.crouch_height_m;
  plan.push_duration_s = 2.0 * stroke_z / plan.takeoff_velocity_m_s.z();
  plan.flight_duration_s = flight_time_s(com_velocity.z(), drop_m);
  // the trunk turns against the legs' angular momentum at take-off (whole-body inertia)
  const Eigen::Vector3d angular = standing_angular_momentum(takeoff_legs, plan.takeoff_velocity_m_s, limits.mass_kg);
  plan.takeoff_tilt_rate_rad_s = {-angular.x() / limits.inertia_diag[0], -angular.y() / limits.inertia_diag[1]};
  plan.push_acceleration_m_s2 = plan.takeoff_velocity_m_s / plan.push_duration_s;
  plan.push_stroke_m = plan.takeoff_velocity_m_s * (0.5 * plan.push_duration_s);
  plan.crouch_offset_m = -0.5 * plan.push_stroke_m.head<2>();
  const Eigen::Vector2d horizontal = com_velocity.head<2>();
  plan.flight_travel_m = {horizontal.x() * plan.flight_duration_s, horizontal.y() * plan.flight_duration_s, -drop_m};
  plan.landing_foot_offset_m = braking_distance(horizontal, limits);
  plan.apex_height_m = limits.takeoff_height_m + com_velocity.z() * com_velocity.z() / (2.0 * kGravityMPerS2);
  plan.planned_displacement_m = planned_displacement(plan);
}

// the plan with the push from limits.crouch_height_m to limits.takeoff_height_m
JumpPlan plan_jump_between(const JumpTarget& target, const JumpLimits& limits) {
  JumpPlan plan;
  const double stroke_z = limits.takeoff_height_m - limits.crouch_height_m;
  const double drop_m = limits.takeoff_height_m - (target.landing_ground_m + limits.touchdown_height_m);

  // the trunk's take-off velocity that gives the centre of mass its own (near diagonal map)
  const TakeoffLegs takeoff = takeoff_legs_of(limits);
  const Eigen::Matrix3d& momentum = takeoff.momentum;
  // trunk horizontal speed per centre-of-mass speed
  const double horizontal_gain = 2.0 / (momentum(0, 0) + momentum(1, 1));

  // vertical: the apex the target asks for, at least the lowest hop and enough to reach a higher landing
  const double rise_m = limits.stand_height_m + target.apex_rise_m - limits.takeoff_height_m;
  double vz = std::max(limits.min_vertical_speed_m_s, std::sqrt(2.0 * kGravityMPerS2 * std::max(rise_m, 0.0)));
  if (drop_m < 0.0) vz = std::max(vz, std::sqrt(-2.0 * kGravityMPerS2 * drop_m) + 0.3);
  // the push's force and the legs' speed cap it
  const VerticalCap cap = vertical_speed_cap(limits, momentum);
  if (vz > cap.speed_m_s) plan.shortfall |= cap.limit;
  vz = std::min(vz, cap.speed_m_s);
  const double vz_cap = cap.speed_m_s;

  // horizontal: crouch offset + stroke + flight + braking after touchdown = distance, for the
  // speed u: u^2 / (2 a_b) + u (stroke_z gain / (2 trunk_vz) + flight) = distance
  const double distance = target.displacement_m.norm();
  const Eigen::Vector2d direction =
      distance > 1e-9 ? Eigen::Vector2d(target.displacement_m / distance) : Eigen::Vector2d::UnitX();
  const double braking = limits.landing_braking_m_s2;
  const auto horizontal_speed = [&](double vertical) {
    const double c = 0.5 * stroke_z * horizontal_gain * momentum(2, 2) / vertical + flight_time_s(vertical, drop_m);
    return braking * (-c + std::sqrt(c * c + 2.0 * distance / braking));
  };
  // a long jump the landing cannot brake flies higher (longer) instead, as far as the legs allow
  constexpr double kVerticalStep = 0.02;
  const double max_h = limits.max_horizontal_speed_m_s;
  while (horizontal_speed(vz) > max_h && vz + kVerticalStep <= vz_cap &&
         std::hypot(max_h, vz + kVerticalStep) <= limits.max_takeoff_speed_m_s) {
    vz += kVerticalStep;
  }
  double u = horizontal_speed(vz);
  if (u > limits.max_horizontal_speed_m_s) {
    u = limits.max_horizontal_speed_m_s;
    plan.shortfall |= kJumpLandingLimited;
  }
  const double u_speed =
      std::sqrt(std::max(limits.max_takeoff_speed_m_s * limits.max_takeoff_speed_m_s - vz * vz, 0.0));
  if (u > u_speed) {
    u = u_speed;
    plan.shortfall |= kJumpSpeedLimited;
  }
  const double trunk_vz = vz / momentum(2, 2);
  const double push_s = 2.0 * stroke_z / trunk_vz;
  // |a_xy| <= mu (a_z + g) for the trunk, with a = v / push_s
  const double u_friction = limits.friction_mu * (trunk_vz / push_s + kGravityMPerS2) * push_s / horizontal_gain;
  if (u > u_friction) {
    u = u_friction;
    plan.shortfall |= kJumpFrictionLimited;
  }
  Eigen::Vector3d com_velocity(u * direction.x(), u * direction.y(), vz);
  finish_plan(plan, com_velocity, drop_m, limits, takeoff);
  // the legs' momentum couples the trunk's horizontal and vertical speeds: correct the centre of
  // mass's horizontal speed until the displacements add up to the target (when reachable)
  if (plan.shortfall == kJumpReachable) {
    for (int iteration = 0; iteration < 4; ++iteration) {
      const Eigen::Vector2d error = target.displacement_m - plan.planned_displacement_m;
      const double slope = plan.flight_duration_s + com_velocity.head<2>().norm() / braking;
      com_velocity.head<2>() += error / slope;
      // never past the landing's limit (the correction is a few millimetres)
      const double speed = com_velocity.head<2>().norm();
      if (speed > max_h) com_velocity.head<2>() *= max_h / speed;
      finish_plan(plan, com_velocity, drop_m, limits, takeoff);
    }
  }
  // the yaw turns at a constant rate from mid-push to touchdown
  plan.yaw_rate_rad_s = target.yaw_rad / (0.5 * plan.push_duration_s + plan.flight_duration_s);
  plan.planned_yaw_rad = target.yaw_rad;
  return plan;
}

}  // namespace

JumpPlan plan_jump(const JumpTarget& target, const JumpLimits& limits) {
  if (target.apex_rise_m <= 0.0) return plan_jump_between(target, limits);
  JumpLimits high = limits;
  high.crouch_height_m = limits.high_jump_crouch_height_m;
  high.takeoff_height_m = limits.high_jump_takeoff_height_m;
  return plan_jump_between(target, high);
}

JumpPlan plan_force_jump(const Eigen::Vector3d& acceleration, double yaw_acceleration, const JumpLimits& limits) {
  JumpPlan plan;
  const double stroke_z = limits.takeoff_height_m - limits.crouch_height_m;
  const double drop_m = limits.takeoff_height_m - limits.touchdown_height_m;
  const TakeoffLegs takeoff = takeoff_legs_of(limits);
  const Eigen::Matrix3d& momentum = takeoff.momentum;
  // the asked acceleration of the centre of mass; NaN or Inf asks nothing
  Eigen::Vector3d a = acceleration;
  for (Eigen::Index k = 0; k < 3; ++k) {
    if (!std::isfinite(a[k])) a[k] = 0.0;
  }
  // within the friction cone (the ground's force is m (a + g))
  const double horizontal_max = limits.friction_mu * (std::max(a.z(), 0.0) + kGravityMPerS2);
  if (a.head<2>().norm() > horizontal_max) {
    a.head<2>() *= horizontal_max / a.head<2>().norm();
    plan.shortfall |= kJumpFrictionLimited;
  }
  // the trunk's acceleration that gives the centre of mass the asked one, over the stroke:
  // v_z^2 = 2 a_z s, the push lasting 2 s / v_z
  const Eigen::Vector3d trunk_a = momentum.inverse() * a;
  const double trunk_vz = std::sqrt(2.0 * stroke_z * std::max(trunk_a.z(), 0.0));
  const double push_s = trunk_vz > 0.0 ? 2.0 * stroke_z / trunk_vz : 0.0;
  Eigen::Vector3d com = a * push_s;
  const VerticalCap cap = vertical_speed_cap(limits, momentum);
  if (com.z() > cap.speed_m_s) plan.shortfall |= cap.limit;
  // below the lowest hop the legs could not swing to the landing pose: the lowest hop, in place
  if (com.z() < limits.min_vertical_speed_m_s) com.head<2>().setZero();
  com.z() = std::clamp(com.z(), limits.min_vertical_speed_m_s, cap.speed_m_s);
  const double u_speed =
      std::sqrt(std::max(limits.max_takeoff_speed_m_s * limits.max_takeoff_speed_m_s - com.z() * com.z(), 0.0));
  const double u_max = std::min(limits.max_horizontal_speed_m_s, u_speed);
  if (com.head<2>().norm() > u_max) {
    plan.shortfall |= u_speed < limits.max_horizontal_speed_m_s ? kJumpSpeedLimited : kJumpLandingLimited;
    com.head<2>() *= u_max / com.head<2>().norm();
  }
  finish_plan(plan, com, drop_m, limits, takeoff);
  // the turn: the asked yaw acceleration through the push, within the turn a jump may make
  const double asked_yaw = std::isfinite(yaw_acceleration) ? yaw_acceleration : 0.0;
  const double max_rate = limits.max_turn_rad / (0.5 * plan.push_duration_s + plan.flight_duration_s);
  plan.yaw_rate_rad_s = std::clamp(asked_yaw * plan.push_duration_s, -max_rate, max_rate);
  plan.planned_yaw_rad = plan.yaw_rate_rad_s * (0.5 * plan.push_duration_s + plan.flight_duration_s);
  return plan;
}

const char* jump_shortfall_text(unsigned shortfall) {
  // every combination of the four bits, named in one order
  static const char* const kTexts[16] = {"",
                                         "take-off speed",
                                         "friction",
                                         "take-off speed, friction",
                                         "leg force",
                                         "take-off speed, leg force",
                                         "friction, leg force",
                                         "take-off speed, friction, leg force",
                                         "landing speed",
                                         "take-off speed, landing speed",
                                         "friction, landing speed",
                                         "take-off speed, friction, landing speed",
                                         "leg force, landing speed",
                                         "take-off speed, leg force, landing speed",
                                         "friction, leg force, landing speed",
                                         "take-off speed, friction, leg force, landing speed"};
  return kTexts[shortfall & 15u];
}

}  // namespace cerebellum
