#include "modes/push_recovery_stand_gait.hpp"

namespace cerebellum {

PushRecoveryStandGait::PushRecoveryStandGait(WalkingGaits& walking, const PushRecoveryStandConfig& config,
                                             double tick_s)
    : WalkingGaitWrapper(walking), config_(config), recovery_(config.recovery), tick_s_(tick_s) {}

LocomotionCommand PushRecoveryStandGait::walking_command() const {
  LocomotionCommand c = command_;
  // a stand takes no velocity; recovering, the trot steps in place (velocity 0) and its footholds'
  // velocity feedback places the feet under the moving body
  c.velocity.setZero();
  c.gait_id = recovery_.stepping() ? config_.stepping_gait_id : command_.gait_id;
  c.catching_push = recovery_.stepping();
  return c;
}

void PushRecoveryStandGait::start(const RobotState& state, const LocomotionCommand& command) {
  command_ = command;
  recovery_.reset();
  walking_.start(state, walking_command());
}

void PushRecoveryStandGait::take_over(const RobotState& state, const LocomotionCommand& command) {
  command_ = command;
  recovery_.reset();
  walking_.take_over(state, walking_command());
}

void PushRecoveryStandGait::stop() {
  walking_.stop();
  recovery_.reset();
}

void PushRecoveryStandGait::run(const RobotState& state, JointCommand& command) {
  recovery_.update(state, tick_s_);
  // recovering, the position loop must not pull the body back to where the push found it: it
  // stands where it comes to rest
  if (recovery_.stepping()) walking_.anchor_position_at_trunk(state);
  walking_.update(walking_command());
  walking_.run(state, command);
}

}  // namespace cerebellum
