// Gait 1 on the walking controller: a stand with push recovery. It stands on all four feet; a push
// its planted feet cannot absorb (control/locomotion/push_recovery) makes it trot in place, the
// footholds catching the body, until the body is at rest; then it stands again where it came to
// rest. Gait 31 (the walking controller's plain stand) keeps its feet planted and only leans.
#pragma once

#include "control/locomotion/push_recovery.hpp"
#include "modes/locomotion_gait.hpp"
#include "modes/walking_gaits.hpp"

namespace cerebellum {

struct PushRecoveryStandConfig {
  PushRecoveryConfig recovery;
  int stepping_gait_id = 3;  // the trot that catches the body (gait table)
};

class PushRecoveryStandGait final : public LocomotionGait {
 public:
  PushRecoveryStandGait(WalkingGaits& walking, const PushRecoveryStandConfig& config, double tick_s);

  const char* check(const HighLevelCommand& command) const override { return walking_.check(command); }
  void start(const RobotState& state, const LocomotionCommand& command) override;
  void update(const LocomotionCommand& command) override { command_ = command; }
  void run(const RobotState& state, JointCommand& command) override;
  ContactPlan contact_plan() const override { return walking_.contact_plan(); }
  void stop() override;
  const void* walking_controller() const override { return &walking_; }
  void take_over(const RobotState& state, const LocomotionCommand& command) override;
  int progress_percent() const override { return 100; }
  bool damping_protection() const override { return walking_.failed(); }

  const PushRecovery& recovery() const { return recovery_; }

 private:
  // the walking controller's command: the stand, or the stepping trot in place while recovering
  LocomotionCommand walking_command() const;

  WalkingGaits& walking_;
  PushRecoveryStandConfig config_;
  PushRecovery recovery_;
  double tick_s_;
  LocomotionCommand command_;
};

}  // namespace cerebellum
