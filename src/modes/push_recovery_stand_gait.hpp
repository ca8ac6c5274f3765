// Gait 1 on the walking controller: a stand with push recovery. It stands on all four feet; a push
// its planted feet cannot absorb (control/locomotion/push_recovery) makes it trot in place, the
// footholds catching the body, until the body is at rest; then it stands again where it came to
// rest. Gait 31 (the walking controller's plain stand) keeps its feet planted and only leans.
#pragma once

#include "control/locomotion/gait_table.hpp"
#include "control/locomotion/push_recovery.hpp"
#include "modes/walking_gait_wrapper.hpp"

namespace cerebellum {

struct PushRecoveryStandConfig {
  PushRecoveryConfig recovery;
  // the trot that catches the body (gait table): the flying trot's 0.3 s cycle and short stance
  // step before the trunk has pitched or rolled a planted foot out of the interface's workspace
  // (gait 3's 0.36 s cycle ended 20 N s shoves along the body in the footpos watch's damping)
  int stepping_gait_id = kFlyingTrotGaitId;
};

class PushRecoveryStandGait final : public WalkingGaitWrapper {
 public:
  PushRecoveryStandGait(WalkingGaits& walking, const PushRecoveryStandConfig& config, double tick_s);

  void start(const RobotState& state, const LocomotionCommand& command) override;
  void update(const LocomotionCommand& command) override { command_ = command; }
  void run(const RobotState& state, JointCommand& command) override;
  void stop() override;
  void take_over(const RobotState& state, const LocomotionCommand& command) override;

  const PushRecovery& recovery() const { return recovery_; }

 private:
  // the walking controller's command: the stand, or the stepping trot in place while recovering
  LocomotionCommand walking_command() const;

  PushRecoveryStandConfig config_;
  PushRecovery recovery_;
  double tick_s_;
  LocomotionCommand command_;
};

}  // namespace cerebellum
