// What is wrong with the body while it stands on its feet: tipped over (ori_error) or a foot
// outside the interface's workspace (footpos_error). Pure functions of the state; which modes are
// watched and what happens then is the state machine's business.
#pragma once

#include "core/leg_kinematics.hpp"
#include "core/robot_state.hpp"
#include "safety/safety_report.hpp"

namespace cerebellum {

inline constexpr double kOrientationErrorRad = 1.3;

// |roll| or |pitch| at or beyond the limit
bool orientation_error(const RobotState& state, double limit_rad = kOrientationErrorRad);

// the foot workspace of the interface (cyberdog2-highlevel.md), L the interface's leg length:
// |x| <= L sin 60 deg, |y| <= L sin 0.68 + abad cos 0.68, -sqrt(L^2 + abad^2) <= z <= -L/6
struct FootWorkspace {
  double forward_m = default_forward_m();
  double lateral_m = default_lateral_m();
  double lowest_m = default_lowest_m();
  double highest_m = default_highest_m();

  static double default_forward_m();
  static double default_lateral_m();
  static double default_lowest_m();
  static double default_highest_m();
};

// footpos_error bits: bit 3 * leg + axis (0 forward, 1 lateral, 2 vertical) for a foot outside
// its workspace, measured from its abad joint in the body frame
int foot_position_error_bits(const RobotState& state, const FootWorkspace& workspace = {});

// a foot target (body frame) moved into the workspace shrunk by margin_m on every side: what a
// controller that steps asks of a swing foot, so that the watch above does not fire on its own steps
Vec3 clamp_into_foot_workspace(std::size_t leg, const Vec3& foot_body, const FootWorkspace& workspace, double margin_m);

struct BodyWatchLimits {
  double orientation_limit_rad = kOrientationErrorRad;
  FootWorkspace workspace;
};

// orientation_error always, footpos_error only when check_feet (a standing mode that lifts feet
// on purpose does not ask for it)
SafetyReport check_body(const RobotState& state, bool check_feet, const BodyWatchLimits& limits = {});

}  // namespace cerebellum
