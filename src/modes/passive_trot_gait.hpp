// Gait 4, the passive trot ("walk the dog"): the robot stands while nothing moves it, trots along
// when a leash or a hand pulls its trunk (control/locomotion/passive_follow), and stands again
// where it is left alone. Commanded velocities add to the pull. It drives the walking gaits'
// controller: the stand pattern while standing, gait 4's trot while it steps.
#pragma once

#include "control/locomotion/passive_follow.hpp"
#include "modes/walking_gait_wrapper.hpp"

namespace cerebellum {

class PassiveTrotGait final : public WalkingGaitWrapper {
 public:
  PassiveTrotGait(WalkingGaits& walking, const PassiveFollowConfig& follow, double tick_s);

  void start(const RobotState& state, const LocomotionCommand& command) override;
  void update(const LocomotionCommand& command) override { command_ = command; }
  void run(const RobotState& state, JointCommand& command) override;
  void stop() override;
  void take_over(const RobotState& state, const LocomotionCommand& command) override;

  const PassiveFollow& follow() const { return follow_; }

 private:
  // the walking controller's command for this tick: the client's plus the pull's velocity
  LocomotionCommand walking_command(const RobotState& state) const;

  PassiveFollow follow_;
  double tick_s_;
  LocomotionCommand command_;
};

}  // namespace cerebellum
