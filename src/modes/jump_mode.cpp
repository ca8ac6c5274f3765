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

JumpPlan force_jump_plan(const HighLevelCommand& command, const JumpLimits& limits) {
  const Eigen::Vector3d acceleration(command.acc_des[0], command.acc_des[1], command.acc_des[2]);
  return plan_force_jump(acceleration, command.acc_des[5], limits);
}

JumpMode::JumpMode(ModeId mode, const JumpControllerConfig& config, FlipPlans flips)
    : mode_(mode), controller_(config), flips_(std::move(flips)) {}

const FlipTrajectory* JumpMode::flip_plan(int gait_id) const {
  if (mode_ != ModeId::Jump3d) return nullptr;
  if (gait_id == kBackFlipGaitId && flips_.back) return &*flips_.back;
  if (gait_id == kFrontFlipGaitId && flips_.front) return &*flips_.front;
  return nullptr;
}

const char* JumpMode::check(const HighLevelCommand& command) const {
  const bool flip = command.gait_id == kBackFlipGaitId || command.gait_id == kFrontFlipGaitId;
  if (mode_ == ModeId::Jump3d && find_jump(command.gait_id) == nullptr && !flip) {
    return "mode 16 jump ids are 0..6 and 9 (20, 21: flips)";
  }
  return nullptr;
}

StartRefusal JumpMode::start_refusal(const RobotState& state, const HighLevelCommand& command) const {
  // a running jump ignores new commands (one-shot): nothing to refuse
  if (flipping() || (!controller_.finished() && controller_.phase() != JumpPhase::Idle)) return {};
  if (mode_ == ModeId::Jump3d && (command.gait_id == kBackFlipGaitId || command.gait_id == kFrontFlipGaitId)) {
    const bool front = command.gait_id == kFrontFlipGaitId;
    switch (flip_gate(state, front ? Flip::Front : Flip::Back)) {
      case FlipGate::OverHeat: return {SwitchStatus::OverHeat, "flip refused: a motor is above 74 deg C"};
      case FlipGate::LowBattery:
        return {SwitchStatus::LowBattery,
                front ? "front flip refused: battery below 50 %" : "back flip refused: battery below 20 %"};
      case FlipGate::Allowed: break;
    }
    if (flip_plan(command.gait_id) == nullptr)
      return {SwitchStatus::BanTransition,
              front ? "front flip refused: no flip file was loaded" : "back flip refused: no flip file was loaded"};
  }
  if (const char* reason = jump_refusal(state)) return {SwitchStatus::BanTransition, reason};
  return {};
}

void JumpMode::enter(const RobotState& state, const HighLevelCommand& command) {
  gait_ = command.gait_id;
  flip_ = FlipRun{};
  if (const FlipTrajectory* plan = flip_plan(command.gait_id)) {
    // the jump gate and the flip gate were passed at the start: the plan plays from this stand
    flip_.start(state, *plan);
    return;
  }
  if (mode_ == ModeId::Jump3d) {
    // the machine enters only with a jump id the table has (flips are refused before)
    const JumpSpec* spec = find_jump(command.gait_id);
    if (spec == nullptr) {
      controller_.hold(state);
      return;
    }
    controller_.start(state, jump_target(*spec));
  } else {
    controller_.start(state, force_jump_plan(command, controller_.config().limits));
  }
}

void JumpMode::update(const RobotState& state, const HighLevelCommand& command) {
  // one-shot: a jump runs to its end; a new command afterwards jumps again
  if (!flipping() && controller_.finished()) enter(state, command);
}

void JumpMode::run(const RobotState& state, JointCommand& command) {
  if (flipping()) {
    flip_time_s_ = state.time_s;
    flip_.compute(state, command);
    if (!flip_.done()) return;
    // down on its feet: the jump controller lands it
    controller_.land(state);
  }
  controller_.compute(state, command);
}

ContactPlan JumpMode::contact_plan() const {
  if (flipping() || controller_.phase() != JumpPhase::Flight) return std::nullopt;
  return ContactSchedule{};  // every foot: probability 0
}

int JumpMode::progress_percent() const {
  // a flip: its own stages to 60 %, then the landing's share of the rest
  if (flipping()) return static_cast<int>(std::floor(flip_.progress(flip_time_s_) * 60.0));
  if (flip_.done()) return 60 + static_cast<int>(std::floor(controller_.progress() * 40.0));
  return static_cast<int>(std::floor(controller_.progress() * 100.0));
}

}  // namespace cerebellum
