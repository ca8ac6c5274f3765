// Gait 1's push recovery: when a push carries the body where its planted feet cannot stop it, the
// stand steps (a trot on the walking controller, its Raibert footholds chasing the body's velocity)
// until the body is at rest, then stands again where it came to rest. Whether a push needs steps is
// judged on the instantaneous capture point (where the body must put its feet to stop, for a linear
// inverted pendulum: p + v sqrt(h / g)) against the feet on the ground, and on the trunk's tipping.
#pragma once

#include <Eigen/Core>

#include "core/robot_state.hpp"

namespace cerebellum {

struct PushRecoveryConfig {
  // steps begin when the capture point leaves the feet's rectangle shrunk by this margin (m) ...
  double capture_margin_m = 0.06;
  // ... or the trunk rolls or pitches faster than this (rad/s): a lateral shove tips the body over
  // its feet before the capture point is out
  double tip_rate_rad_s = 1.0;
  // ... or the trunk moves faster than this (m/s): a standing body at this speed is being pushed.
  // A push that goes on (50 N for 0.5 s) is held longest by four planted feet, which take the roll
  // it causes over the whole track, where a trotting pair has one foot per side: stepping at
  // 0.3 m/s instead fell in 8 of 20 runs of 25 N s from the side
  double start_speed_m_s = 0.45;
  // ... or it moves faster than shove_speed_m_s while accelerating beyond shove_accel_m_s2: a
  // short blow (0.1 s of 150 N gives 17 m/s^2, a steady 50 N push 6) is over before the planted
  // feet could work against it, so the steps begin as soon as possible
  double shove_speed_m_s = 0.3;
  double shove_accel_m_s2 = 10.0;
  // at rest again: horizontal speed and tipping rate below these for settle_hold_s
  double settle_speed_m_s = 0.1;
  double settle_tip_rate_rad_s = 0.3;
  double settle_hold_s = 0.4;
};

// the instantaneous capture point of the trunk (world x, y): position + velocity sqrt(h / g), h the
// trunk's height over the ground
Eigen::Vector2d capture_point_world(const RobotState& state);

// how far (m) a world point lies outside the rectangle the four feet span in the heading frame
// (negative: inside, by the distance to its nearest edge)
double distance_outside_feet(const RobotState& state, const Eigen::Vector2d& point_world);

class PushRecovery {
 public:
  explicit PushRecovery(const PushRecoveryConfig& config = {}) : config_(config) {}

  void reset();
  // one tick of dt_s while the robot stands or recovers; true while it must step
  bool update(const RobotState& state, double dt_s);
  bool stepping() const { return stepping_; }
  // recoveries begun since the last reset (telemetry, tests)
  int recoveries() const { return recoveries_; }

 private:
  PushRecoveryConfig config_;
  bool stepping_ = false;
  double quiet_s_ = 0.0;
  int recoveries_ = 0;
};

}  // namespace cerebellum
