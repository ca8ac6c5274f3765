// Whether the robot may leave the ground now (a jump's start): it stands on all four feet, still,
// level, on level ground, with healthy motors. Pure function of the state; the jump modes ask it
// before they start and the state machine refuses with the reason (BAN_TRANS).
#pragma once

#include "core/robot_state.hpp"

namespace cerebellum {

struct JumpGateLimits {
  double max_speed_m_s = 0.3;     // trunk speed over the ground
  double max_yaw_rate_rad_s = 0.5;
  double max_tilt_rad = 0.25;     // trunk roll or pitch
  double max_slope_rad = 0.09;    // ground plane (about 5 deg)
  double min_height_m = 0.15;     // standing, not lying
  int min_feet_down = 4;
};

// nullptr when a jump may start, else why not (a static string)
const char* jump_refusal(const RobotState& state, const JumpGateLimits& limits = {});

}  // namespace cerebellum
