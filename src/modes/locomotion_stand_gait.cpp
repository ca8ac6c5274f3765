#include "modes/locomotion_stand_gait.hpp"

#include <cmath>

namespace cerebellum {

LocomotionStandGait::LocomotionStandGait(const LocomotionStandConfig& config) : config_(config), stand_(config.stand) {}

void LocomotionStandGait::start(const RobotState& state, const LocomotionCommand& command) {
  stand_.start(state);
  update(command);
}

void LocomotionStandGait::update(const LocomotionCommand& command) {
  QpStandGoal goal;
  goal.pose.rpy = {0.0, command.pitch_rad, 0.0};
  goal.pose.position = {0.0, 0.0, command.height_m};
  goal.hold_position_xy = command.gait_id != kWithoutPushRecovery;
  stand_.set_goal(goal, config_.speed);
}

void LocomotionStandGait::run(const RobotState& state, JointCommand& command) { stand_.compute(state, command); }

int LocomotionStandGait::progress_percent() const { return static_cast<int>(std::floor(stand_.progress() * 100.0)); }

}  // namespace cerebellum
