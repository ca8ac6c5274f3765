// Whether the robot may leave the ground now (a jump's start): it stands on all four feet, still,
// level, on level ground, with healthy motors; a flip also with motors below 74 deg C and enough
// charge. Pure functions of the state; the jump modes ask them before they start and the state
// machine refuses with the reason (BAN_TRANS, OVER_HEAT, LOW_BAT).
#pragma once

#include "core/robot_state.hpp"

namespace cerebellum {

struct JumpGateLimits {
  double max_speed_m_s = 0.3;  // trunk speed over the ground
  double max_yaw_rate_rad_s = 0.5;
  double max_tilt_rad = 0.25;   // trunk roll or pitch
  double max_slope_rad = 0.09;  // ground plane (about 5 deg)
  double min_height_m = 0.15;   // standing, not lying
  int min_feet_down = 4;
};

// nullptr when a jump may start, else why not (a static string)
const char* jump_refusal(const RobotState& state, const JumpGateLimits& limits = {});

// a flip also needs cool motors and charge (cyberdog2-highlevel.md, switch_status 6 and 7)
enum class Flip { Back, Front };
enum class FlipGate { Allowed, OverHeat, LowBattery };
struct FlipGateLimits {
  double max_motor_temperature_c = 74.0;
  double back_flip_min_battery_percent = 20.0;
  double front_flip_min_battery_percent = 50.0;
};
FlipGate flip_gate(const RobotState& state, Flip flip, const FlipGateLimits& limits = {});

}  // namespace cerebellum
