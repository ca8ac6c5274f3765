#include "modes/walking_gaits.hpp"

#include <algorithm>
#include <cmath>

#include "safety/damping_command.hpp"

namespace cerebellum {

LocomotionTarget locomotion_target_from(const LocomotionCommand& command) {
  LocomotionTarget target;
  target.gait = *gait_pattern(command.gait_id);
  // the limits the mode clamped to, which the controller holds its ramp and gait changes within
  if (command.velocity_limits) {
    for (int axis = 0; axis < 3; ++axis) {
      target.gait.velocity_min[static_cast<std::size_t>(axis)] = command.velocity_limits->min[axis];
      target.gait.velocity_max[static_cast<std::size_t>(axis)] = command.velocity_limits->max[axis];
    }
  }
  target.velocity = command.velocity;
  target.height_m = command.height_m;
  target.pitch_rad = command.pitch_rad;
  // as commanded: LocomotionMode::clamped has put them into its LocomotionLimits
  target.step_height_front_m = command.step_height_m[0];
  target.step_height_rear_m = command.step_height_m[1];
  target.vertical_legs = (command.value & 0b10) != 0;
  // the table's stands (1, 31) hold the trunk over their planted feet; gait 1 steps when a push
  // is more than that (push_recovery_stand_gait)
  const GaitSpec* spec = find_gait(command.gait_id);
  target.stand_holds_position = spec != nullptr && !gait_steps(*spec);
  target.catching_push = command.catching_push;
  return target;
}

WalkingGaits::WalkingGaits(const WalkingGaitsConfig& config, std::unique_ptr<qp::QpSolver> solver)
    : config_(config), controller_(config.locomotion, std::move(solver)) {}

const char* WalkingGaits::check(const HighLevelCommand& command) const {
  if (!gait_pattern(command.gait_id)) return "gait not available in mode 11";
  for (float v : command.vel_des) {
    if (!std::isfinite(v)) return "non-finite velocity in a locomotion command";
  }
  return nullptr;
}

void WalkingGaits::start(const RobotState& state, const LocomotionCommand& command) {
  controller_.set_command(locomotion_target_from(command));
  controller_.reset(state);
}

void WalkingGaits::update(const LocomotionCommand& command) {
  controller_.set_command(locomotion_target_from(command));
}

void WalkingGaits::stop() { plan_.reset(); }

void WalkingGaits::run(const RobotState& state, JointCommand& command) {
  if (failed()) {
    // no trustworthy stance forces: soft joints, the robot sinks to the ground
    command = damping_command(config_.failure_damping_kd, state.q);
    return;
  }
  controller_.compute(state, command);
  // standing, the estimator judges the feet by their load (a shove lifts planted feet)
  plan_ = controller_.standing() ? ContactPlan{} : ContactPlan{controller_.contact_schedule()};
}

}  // namespace cerebellum
