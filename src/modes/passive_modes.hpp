// Off (0) and PureDamper (7): the modes in which the motors do not hold a pose.
#pragma once

#include <array>

#include "core/robot_model.hpp"
#include "control/stand_up_controller.hpp"
#include "modes/mode.hpp"

namespace cerebellum {

// mode 0: motors passive
class OffMode final : public Mode {
 public:
  ModeId id() const override { return ModeId::Off; }
  const char* check(const HighLevelCommand& command) const override;
  void enter(const RobotState&, const HighLevelCommand&) override {}
  void update(const RobotState&, const HighLevelCommand&) override {}
  void run(const RobotState& state, JointCommand& command) override;
  int gait_id() const override { return 0; }
  int progress_percent() const override { return 100; }
};

struct PureDamperConfig {
  double damping_kd = robot::kDampingKd;  // gait 0: joint damping, the robot sinks by itself
  double lie_down_duration_s = 1.0;       // gait 1: joints driven to the lying pose over this time
  double lie_down_kp = 40.0;
  double lie_down_kd = 2.0;
  std::array<double, 3> lying_pose;  // abad, hip, knee (SDK convention)
};
PureDamperConfig default_pure_damper_config();

// mode 7: gait 0 passive lie-down (high damping), gait 1 active lie-down to the lying pose
class PureDamperMode final : public Mode {
 public:
  explicit PureDamperMode(const PureDamperConfig& config);
  ModeId id() const override { return ModeId::PureDamper; }
  const char* check(const HighLevelCommand& command) const override;
  void enter(const RobotState& state, const HighLevelCommand& command) override;
  void update(const RobotState& state, const HighLevelCommand& command) override;
  void run(const RobotState& state, JointCommand& command) override;
  int gait_id() const override { return gait_; }
  int progress_percent() const override;

 private:
  PureDamperConfig config_;
  int gait_ = 0;
  double start_time_s_ = 0.0;
  double elapsed_s_ = 0.0;
  JointArray<double> start_q_{};
  bool started_ = false;
};

}  // namespace cerebellum
