// Picked up or set down? While a standing mode runs: the robot counts as lifted when no foot
// carries load and the body is held up or pulled up (the IMU's vertical specific force stays
// well above free fall) and has risen (vertical speed integrated from the IMU). While lifted:
// it counts as set down again once enough feet carry load. The caller owns the small state the
// integrals need (LiftWatch) and resets it when the mode changes.
#pragma once

#include "core/robot_state.hpp"

namespace cerebellum {

struct LiftDetectorConfig {
  double unloaded_time_s = 0.1;       // all feet without load this long
  double min_support_fraction = 0.5;  // vertical specific force above this fraction of g (not falling)
  double min_rise_m = 0.03;           // body rose at least this much ...
  double min_rise_speed_m_s = 0.2;    // ... or rises at least this fast
  double integration_leak_s = 1.0;    // time constant that keeps the IMU integrals from drifting
  int landed_feet = 3;                // feet with load that count as set down
  double landed_time_s = 0.1;
};

// what the lift decision remembers from tick to tick
struct LiftWatch {
  double last_time_s = 0.0;
  bool has_time = false;
  double unloaded_s = 0.0;
  double rise_speed_m_s = 0.0;
  double rise_m = 0.0;
  double loaded_s = 0.0;
};

// one tick of a standing mode: true once the robot has been picked up
bool detect_lifted(const RobotState& state, LiftWatch& watch, const LiftDetectorConfig& config = {});
// one tick while lifted: true once the feet carry the robot again
bool detect_landed(const RobotState& state, LiftWatch& watch, const LiftDetectorConfig& config = {});

}  // namespace cerebellum
