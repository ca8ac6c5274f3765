#include "modes/passive_trot_gait.hpp"

#include <cmath>

#include "control/locomotion/gait_table.hpp"

namespace cerebellum {

PassiveTrotGait::PassiveTrotGait(WalkingGaits& walking, const PassiveFollowConfig& follow, double tick_s)
    : WalkingGaitWrapper(walking), follow_(follow), tick_s_(tick_s) {}

LocomotionCommand PassiveTrotGait::walking_command(const RobotState& state) const {
  LocomotionCommand c = command_;
  // the pull's velocity, world frame, turned into the body's heading
  const double yaw = state.rpy.z();
  const Eigen::Vector2d pull = follow_.velocity_world();
  const Eigen::Vector2d pull_body(std::cos(yaw) * pull.x() + std::sin(yaw) * pull.y(),
                                  -std::sin(yaw) * pull.x() + std::cos(yaw) * pull.y());
  c.velocity.head<2>() += pull_body;
  const bool commanded = command_.velocity.norm() > 1e-3;
  // the trot's own limits clamp the sum (the controller reads them from the gait table)
  c.gait_id = follow_.following() || commanded ? kPassiveTrotGaitId : kStandGaitId;
  if (c.gait_id == kStandGaitId) c.velocity.setZero();
  return c;
}

void PassiveTrotGait::start(const RobotState& state, const LocomotionCommand& command) {
  command_ = command;
  follow_.reset();
  walking_.start(state, walking_command(state));
}

void PassiveTrotGait::take_over(const RobotState& state, const LocomotionCommand& command) {
  command_ = command;
  follow_.reset();
  walking_.update(walking_command(state));
}

void PassiveTrotGait::stop() {
  walking_.stop();
  follow_.reset();
}

void PassiveTrotGait::run(const RobotState& state, JointCommand& command) {
  const bool was_following = follow_.following();
  if (state.valid) follow_.update(state, tick_s_);
  // let go: it stands where it is, the position loop does not pull it back along the way it came
  if (was_following && !follow_.following()) walking_.anchor_position_at_trunk(state);
  walking_.update(walking_command(state));
  walking_.run(state, command);
}

}  // namespace cerebellum
