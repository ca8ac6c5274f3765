// Mode 64, the two-leg stand (gait 0; the reference's "greeting", > 8700 ms): the robot rises onto
// its hind legs, holds the upright pose for the rest of the command's duration and comes down onto
// four feet (control/upright/two_leg_stand_controller). One-shot like a jump: a new command of the
// mode while it runs is ignored; once it stands again a new command (a new life_count) rises again.
// The response shows 64 / 0 with the share of the motion done; at 100 it stands in the mode.
#pragma once

#include "control/upright/two_leg_stand_controller.hpp"
#include "modes/mode.hpp"

namespace cerebellum {

class TwoLegStandMode final : public Mode {
 public:
  explicit TwoLegStandMode(const TwoLegStandConfig& config);
  ModeId id() const override { return ModeId::TwoLegStand; }
  const char* check(const HighLevelCommand& command) const override;
  StartRefusal start_refusal(const RobotState& state, const HighLevelCommand& command) const override;
  void enter(const RobotState& state, const HighLevelCommand& command) override;
  void update(const RobotState& state, const HighLevelCommand& command) override;
  void run(const RobotState& state, JointCommand& command) override { controller_.compute(state, command); }
  int gait_id() const override { return 0; }
  int progress_percent() const override;
  bool holds_entry() const override { return !controller_.finished(); }
  bool damping_protection() const override { return controller_.failed(); }
  bool must_finish() const override;

  const TwoLegStandController& controller() const { return controller_; }

 private:
  TwoLegStandController controller_;
};

}  // namespace cerebellum
