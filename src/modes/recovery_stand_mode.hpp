// Mode 12: stand up from wherever the robot is. Upright (lying on its belly or standing): fold
// the legs to the lying pose, then rise. On its back or side: first roll over onto the belly
// (SelfRighting), check the orientation again, and repeat (over the other flank) until upright.
// A body that tips onto its back or side while rising (entered while still falling, or pushed
// over) is rolled again.
// Gait 17 / 18 roll over the left / right flank ("lie on the left / right side first"); gait 0
// rolls over the flank the body leans towards.
#pragma once

#include "control/self_righting.hpp"
#include "control/stand_up_controller.hpp"
#include "modes/mode.hpp"

namespace cerebellum {

class RecoveryStandMode final : public Mode {
 public:
  static constexpr int kRollOverLeft = 17;
  static constexpr int kRollOverRight = 18;

  explicit RecoveryStandMode(const StandUpConfig& config, const SelfRightingConfig& righting = {});
  ModeId id() const override { return ModeId::RecoveryStand; }
  const char* check(const HighLevelCommand& command) const override;
  void enter(const RobotState& state, const HighLevelCommand& command) override;
  void update(const RobotState& state, const HighLevelCommand& command) override;
  void run(const RobotState& state, JointCommand& command) override;
  int gait_id() const override { return gait_; }
  int progress_percent() const override;

  // rolls started since the mode was entered
  int roll_attempts() const { return roll_attempts_; }

 private:
  enum class Phase { Assess, Righting, StandingUp };
  // which flank to roll over from this rest, on this attempt
  BodyRest roll_flank(BodyRest rest, const RobotState& state) const;

  StandUpController stand_up_;
  SelfRighting righting_;
  Phase phase_ = Phase::Assess;
  int gait_ = 0;
  int roll_attempts_ = 0;
};

}  // namespace cerebellum
