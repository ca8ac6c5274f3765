// Mode 12: stand up from wherever the robot is: fold the legs to the lying pose, then rise.
#pragma once

#include "control/stand_up_controller.hpp"
#include "modes/mode.hpp"

namespace cerebellum {

class RecoveryStandMode final : public Mode {
 public:
  explicit RecoveryStandMode(const StandUpConfig& config);
  ModeId id() const override { return ModeId::RecoveryStand; }
  const char* check(const HighLevelCommand& command) const override;
  void enter(const RobotState& state, const HighLevelCommand& command) override;
  void update(const RobotState& state, const HighLevelCommand& command) override;
  void run(const RobotState& state, JointCommand& command) override;
  int gait_id() const override { return gait_; }
  int progress_percent() const override;

 private:
  StandUpController stand_up_;
  int gait_ = 0;
};

}  // namespace cerebellum
