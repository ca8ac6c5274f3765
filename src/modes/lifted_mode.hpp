// Mode 9: the robot has been picked up. The machine enters it by itself (LiftDetector) from the
// standing modes; the legs go to a soft hold of the stand pose so the robot can be set down on
// them; the machine returns to the stand once the feet carry the robot again.
#pragma once

#include <array>

#include "modes/mode.hpp"

namespace cerebellum {

struct LiftedConfig {
  double kp = 12.0;  // soft: a leg gives way when pushed
  double kd = 0.6;
  double move_duration_s = 0.5;     // current joints -> stand pose
  std::array<double, 3> hold_pose;  // abad, hip, knee (SDK convention)
};
LiftedConfig default_lifted_config();

class LiftedMode final : public Mode {
 public:
  explicit LiftedMode(const LiftedConfig& config);
  ModeId id() const override { return ModeId::Lifted; }
  // clients cannot ask for it
  const char* check(const HighLevelCommand& command) const override;
  void enter(const RobotState& state, const HighLevelCommand& command) override;
  void update(const RobotState&, const HighLevelCommand&) override {}
  void run(const RobotState& state, JointCommand& command) override;
  int gait_id() const override { return 0; }
  int progress_percent() const override { return 100; }

 private:
  LiftedConfig config_;
  JointArray<double> start_q_{};
  double start_time_s_ = 0.0;
};

}  // namespace cerebellum
