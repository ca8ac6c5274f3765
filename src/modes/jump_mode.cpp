#include "modes/jump_mode.hpp"

#include <cmath>

#include "core/robot_model.hpp"
#include "safety/jump_gate.hpp"

namespace cerebellum {

const JumpSpec* find_jump(int gait_id) {
  for (const JumpSpec& spec : kJump3dTable) {
    if (spec.gait_id == gait_id) return &spec;
  }
  return nullptr;
}

JumpTarget jump_target(const JumpSpec& spec) {
  JumpTarget target;
  target.displacement_m = {spec.forward_m, spec.left_m};
  target.yaw_rad = robot::deg(spec.turn_deg);
  target.apex_rise_m = spec.apex_rise_m;
  target.landing_ground_m = spec.landing_ground_m;
  return target;
}

JumpMode::JumpMode(const JumpControllerConfig& config) : controller_(config) {}

const char* JumpMode::check(const HighLevelCommand& command) const {
  if (find_jump(command.gait_id) == nullptr) return "mode 16 jump ids are 0..6 and 9";
  return nullptr;
}

const char* JumpMode::start_refusal(const RobotState& state) const {
  // a new jump starts only from a finished one (the same command repeated does not jump again)
  if (!controller_.finished() && controller_.phase() != JumpPhase::Idle) return nullptr;
  return jump_refusal(state);
}

void JumpMode::enter(const RobotState& state, const HighLevelCommand& command) {
  gait_ = command.gait_id;
  controller_.start(state, jump_target(*find_jump(command.gait_id)));
}

void JumpMode::update(const RobotState& state, const HighLevelCommand& command) {
  // one-shot: a jump runs to its end; a new command afterwards jumps again
  if (controller_.finished()) enter(state, command);
}

void JumpMode::run(const RobotState& state, JointCommand& command) { controller_.compute(state, command); }

int JumpMode::progress_percent() const { return static_cast<int>(std::floor(controller_.progress() * 100.0)); }

}  // namespace cerebellum
