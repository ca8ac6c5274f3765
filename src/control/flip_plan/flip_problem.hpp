// What the flip planner is asked (phases, limits, the turn) and what it found. The planner itself
// (flip_nlp) transcribes it for IPOPT; this header keeps IPOPT out of its users.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/robot_model.hpp"

namespace cerebellum::flip {

// the phases in their order: the four feet push, the rear pair alone pushes the body over the
// front, flight
enum FlipPhase : int { kBothPairsPush = 0, kRearPairPushes = 1, kFlight = 2, kFlipPhases = 3 };
// which pair pushes alone in the second phase (planar_model's Pair: 0 front, 1 rear)
inline constexpr int kFrontPairLast = 0;
inline constexpr int kRearPairLast = 1;
const char* flip_phase_name(int phase);

struct FlipLimits {
  double torque_max_nm = robot::kTorqueMaxNm;  // per motor; experiments raise it, the shipped plan does not
  double full_torque_speed_rad_s = robot::kFullTorqueSpeedRadS;
  double no_load_speed_rad_s = robot::kNoLoadSpeedRadS;
  // the horizontal force within this share of the normal force: the jump planner's margin under
  // the simulated feet's 0.8
  double friction_mu = 0.6;
  // a stance foot carries at least this (N, each foot): a plan that barely loads a foot lets it
  // lift on the simulated body, where the contacts and the legs differ a little from the model
  double stance_force_min_n = 15.0;
  double trunk_height_min_m = 0.12;  // the trunk origin above the ground (the trunk box is 0.0545 m thick below it)
  double landing_distance_max_m = 0.5;
  // the trunk still turning at most this fast when the feet reach the ground: the landing stand
  // absorbs a fall, not a spin
  double landing_pitch_rate_max_rad_s = 8.0;
  // the legs at touchdown: each joint within this of the stand pose and turning at most this fast
  double landing_pose_tolerance_rad = 0.5;
  double landing_joint_rate_max_rad_s = 10.0;
};

struct FlipRequest {
  FlipLimits limits;
  // the pitch turned by the end of the flight (rad, SDK sign: a back flip is negative); 0 asks
  // the largest back turn the limits allow (the objective becomes the turn)
  double pitch_turn_rad = -2.0 * robot::kPi;
  // the pair that pushes alone before the flight: the rear for a back flip (the body goes over
  // it backwards); a front flip asks the front pair and a positive turn
  int last_pushing_pair = kRearPairLast;
  std::array<int, kFlipPhases> intervals{20, 14, 26};
  std::array<double, kFlipPhases> duration_min_s{0.15, 0.08, 0.25};
  // short pushes: the played plan is open loop until it lands, and a slow lean over the rear feet
  // would be a balance no feed-forward keeps
  std::array<double, kFlipPhases> duration_max_s{0.4, 0.25, 0.8};
  int max_iterations = 3000;
  bool print = false;
};

// one knot of the planned motion; joints and torques per motor in the order front hip, front
// knee, rear hip, rear knee (both legs of a pair alike)
struct FlipKnot {
  double time_s;
  int phase;
  std::array<double, 3> trunk;  // x (m), z (m), pitch (rad)
  std::array<double, 4> q_rad;
  std::array<double, 4> qd_rad_s;
  std::array<double, 4> tau_nm;
  std::array<double, 4> foot_force_n;  // one foot of the front pair x, z; of the rear pair x, z
};

struct FlipPlan {
  bool solved = false;        // IPOPT reached a point within its tolerances
  // every constraint met within 1e-6 (the limits, the stance, the dynamics), even where the
  // effort's optimality did not converge: a plan that can be played
  bool feasible = false;
  double max_constraint_violation = 0.0;
  std::string status;         // IPOPT's words
  std::vector<FlipKnot> knots;
  double pitch_turned_rad = 0.0;
  std::array<double, 4> peak_torque_nm{};
  std::array<double, kFlipPhases> duration_s{};
  double max_dynamics_residual = 0.0;  // largest violated constraint at the end
};

FlipPlan plan_flip(const FlipRequest& request);

}  // namespace cerebellum::flip
