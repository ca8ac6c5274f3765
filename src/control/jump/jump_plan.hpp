// A jump planned from its target: the ballistic flight that carries the trunk from take-off to
// touchdown, the straight constant-acceleration push-off that produces that take-off velocity
// from a crouch, and where the feet land. Pure maths, frames at take-off: x forward along the
// body's heading, y left, z up; heights are trunk heights above the ground.
//
// Push: the trunk moves on a straight line from the crouch (trunk over the feet) with constant
// acceleration a for T_p; stroke s = v T_p / 2 where v is the take-off velocity, so s is parallel
// to v and s_z = takeoff_height - crouch_height fixes T_p = 2 s_z / v_z.
// Flight: z(t) = takeoff_height + v_z t - g t^2 / 2 down to the touchdown height.
// Landing: the feet touch down ahead of the trunk by what the landing's braking will carry it.
// Displacement = crouch offset + push stroke + flight + foot offset at touchdown (the stand ends
// centred over the feet), and the yaw turns at a constant rate through half the push and all of the flight.
#pragma once

#include <array>

#include <Eigen/Core>

#include "core/robot_model.hpp"

namespace cerebellum {

struct JumpTarget {
  Eigen::Vector2d displacement_m = Eigen::Vector2d::Zero();  // where the stand ends: forward, left
  double yaw_rad = 0.0;                                      // turn, counter-clockwise positive
  // trunk apex above the stand height (0: the lowest hop that clears; > 0: a jump for height)
  double apex_rise_m = 0.0;
  // ground height at the landing relative to the take-off (negative: a step down)
  double landing_ground_m = 0.0;
};

struct JumpLimits {
  double stand_height_m = robot::kStandHeightM;
  double crouch_height_m = 0.13;
  double takeoff_height_m = 0.27;
  // a jump for height asks the legs for more speed than they have near full extension (the
  // motors' torque falls with speed, robot::kFullTorqueSpeedRadS .. kNoLoadSpeedRadS): its push is
  // planned from a deeper crouch to reach the take-off speed lower, where the knees still have
  // lever, and goes on toward full extension while the trunk is slower (the jump controller)
  double high_jump_crouch_height_m = 0.12;
  double high_jump_takeoff_height_m = 0.22;
  double touchdown_height_m = 0.25;     // trunk above the landing ground when the feet touch
  double min_vertical_speed_m_s = 1.2;  // lowest hop: the legs swing to the landing pose in the air
  double max_takeoff_speed_m_s = 2.6;   // centre of mass; the legs' extension speed (motors' speed-torque curve)
  double friction_mu = 0.6;             // planned horizontal push within this share of the normal force
  double max_vertical_force_n = 520.0;  // the four legs together at the push's knee angles
  double mass_kg = robot::kTotalMassKg;
  std::array<double, 3> inertia_diag = robot::kMpcInertiaDiag;  // whole body, about its centre of mass
  double landing_braking_m_s2 = 8.0;                            // horizontal deceleration the landing stand gives
  // the fastest horizontal take-off (centre of mass) whose landing the stand absorbs: faster, the
  // feet land so far ahead that the trunk pitches over them
  double max_horizontal_speed_m_s = 1.2;
  double max_turn_rad = 1.5707963267948966;  // a force jump turns at most this far
};

// what stops a jump from reaching its target (bits; 0: reachable as planned)
enum JumpShortfall : unsigned {
  kJumpReachable = 0,
  kJumpSpeedLimited = 1,     // take-off speed above what the legs can produce
  kJumpFrictionLimited = 2,  // the push would slip
  kJumpForceLimited = 4,     // the push needs more force than the legs have
  kJumpLandingLimited = 8,   // the landing could not brake the horizontal speed
};

struct JumpPlan {
  double crouch_height_m = 0.0;
  // the trunk in the crouch, from its stand over the feet: back by half the stroke, so that the
  // legs lean as little at the push's start as at its end
  Eigen::Vector2d crouch_offset_m = Eigen::Vector2d::Zero();
  double takeoff_height_m = 0.0;
  double push_duration_s = 0.0;
  // the centre of mass's velocity at take-off (it flies the ballistic path) and the trunk's that
  // carries it: the legs, half the robot's mass, are still at rest at their feet
  Eigen::Vector3d com_takeoff_velocity_m_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d takeoff_velocity_m_s = Eigen::Vector3d::Zero();
  Eigen::Matrix3d momentum_map = Eigen::Matrix3d::Identity();        // standing_momentum_map at take-off
  Eigen::Vector3d push_acceleration_m_s2 = Eigen::Vector3d::Zero();  // constant, gravity not included
  Eigen::Vector3d push_stroke_m = Eigen::Vector3d::Zero();           // trunk travel during the push
  double yaw_rate_rad_s = 0.0;                                       // at take-off
  // the trunk's roll and pitch rates at take-off that leave the whole robot without angular
  // momentum (the extending legs carry some): the flight stays level
  Eigen::Vector2d takeoff_tilt_rate_rad_s = Eigen::Vector2d::Zero();
  double flight_duration_s = 0.0;
  Eigen::Vector3d flight_travel_m = Eigen::Vector3d::Zero();        // trunk, take-off to touchdown
  Eigen::Vector2d landing_foot_offset_m = Eigen::Vector2d::Zero();  // feet ahead of the trunk at touchdown
  double apex_height_m = 0.0;                                       // trunk above the take-off ground
  unsigned shortfall = kJumpReachable;
  // what the plan reaches (equals the target when shortfall is 0)
  Eigen::Vector2d planned_displacement_m = Eigen::Vector2d::Zero();
  double planned_yaw_rad = 0.0;
};

JumpPlan plan_jump(const JumpTarget& target, const JumpLimits& limits);

// a jump from the take-off accelerations a client asks for (mode 22, acc_des): the centre of
// mass's linear acceleration during the push (m/s^2, take-off frame, gravity not included) and
// the trunk's yaw acceleration (rad/s^2), clamped to what the legs, the ground and the landing allow (shortfall
// says which); NaN or Inf counts as 0
JumpPlan plan_force_jump(const Eigen::Vector3d& acceleration, double yaw_acceleration, const JumpLimits& limits);

// time from take-off until the centre of mass, rising at vz, comes down by drop_m (negative: rises)
double flight_time_s(double vz, double drop_m);

// how far the landing carries the centre of mass while it brakes this horizontal velocity
// (limits.landing_braking_m_s2): where the feet land ahead of it
Eigen::Vector2d braking_distance(const Eigen::Vector2d& com_horizontal_velocity, const JumpLimits& limits);

// the robot's linear momentum per unit mass when the trunk moves at v (level, not turning) and
// every foot stands still: K v, K = I - (1 / M) sum_legs leg_mass_jacobian J_foot^-1, for the legs at
// these joint angles (abad, hip, knee per leg)
Eigen::Matrix3d standing_momentum_map(const std::array<Eigen::Vector3d, 4>& leg_q, double mass_kg);

// the robot's angular momentum about its centre of mass (body axes, level) when the trunk moves
// at v without turning and every foot stands still: the links as point masses plus their spin
// about the joint axes
Eigen::Vector3d standing_angular_momentum(const std::array<Eigen::Vector3d, 4>& leg_q, const Eigen::Vector3d& v,
                                          double mass_kg);

// what a plan reaches: the displacement its stroke, flight and landing offset add up to
Eigen::Vector2d planned_displacement(const JumpPlan& plan);

// a text naming the shortfall bits ("take-off speed, friction"), "" for none; static storage
const char* jump_shortfall_text(unsigned shortfall);

}  // namespace cerebellum
