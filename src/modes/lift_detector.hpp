// Picked up or set down? While a standing mode runs: the robot counts as lifted when no foot
// carries load and the body is held up or pulled up (the IMU's vertical specific force stays
// well above free fall) and has risen (vertical speed integrated from the IMU). While lifted:
// it counts as set down again once enough feet carry load.
#pragma once

#include "core/robot_state.hpp"
#include "modes/high_level_command.hpp"

namespace cerebellum {

struct LiftDetectorConfig {
  double unloaded_time_s = 0.1;          // all feet without load this long
  double min_support_fraction = 0.5;     // vertical specific force above this fraction of g (not falling)
  double min_rise_m = 0.03;              // body rose at least this much ...
  double min_rise_speed_m_s = 0.2;       // ... or rises at least this fast
  double integration_leak_s = 1.0;       // time constant that keeps the IMU integrals from drifting
  int landed_feet = 3;                   // feet with load that count as set down
  double landed_time_s = 0.1;
};

class LiftDetector {
 public:
  explicit LiftDetector(const LiftDetectorConfig& config = {});
  void reset();
  // one tick of a standing mode: true once the robot has been picked up
  bool lifted(const RobotState& state);
  // one tick while lifted: true once the feet carry the robot again
  bool landed(const RobotState& state);

 private:
  double step_s(const RobotState& state);

  LiftDetectorConfig config_;
  double last_time_s_ = 0.0;
  bool has_time_ = false;
  double unloaded_s_ = 0.0;
  double rise_speed_m_s_ = 0.0;
  double rise_m_ = 0.0;
  double loaded_s_ = 0.0;
};

// the command the MC resumes with when the robot is set down after a lift in `lifted_from`:
// QP stand and locomotion stand as they were (walking gaits stand first), pose control -> QP stand
HighLevelCommand command_after_landing(const HighLevelCommand& lifted_from);

}  // namespace cerebellum
