#include "modes/motion_mode.hpp"

#include <algorithm>
#include <cmath>

#include "control/locomotion/gait_table.hpp"
#include "modes/pose_control_mode.hpp"

namespace cerebellum {
namespace {

HighLevelCommand stand_up_step() {
  HighLevelCommand step;
  step.mode = static_cast<int>(ModeId::RecoveryStand);
  return step;
}

// a step that runs a user gait (the motion's own)
bool runs_user_gait(const HighLevelCommand& step) {
  return step.mode == static_cast<int>(ModeId::Locomotion) && step.gait_id == kUserGaitId;
}

}  // namespace

MotionMode::MotionMode(const MotionLibrary& library, const StepModes& step_modes, const UserGaitSlot& user_gaits,
                       UserGaitRunner& user_gait_runner, const MotionModeConfig& config)
    : library_(library),
      step_modes_(step_modes),
      user_gaits_(user_gaits),
      user_gait_runner_(user_gait_runner),
      config_(config) {
  user_gait_motion_.id = kUserGaitId;
  user_gait_motion_.name = "uploaded user gait";
  HighLevelCommand run_gait;
  run_gait.mode = static_cast<int>(ModeId::Locomotion);
  run_gait.gait_id = kUserGaitId;
  user_gait_motion_.steps = {run_gait};
}

Mode* MotionMode::step_mode(int mode) const {
  for (Mode* m : step_modes_) {
    if (m != nullptr && static_cast<int>(m->id()) == mode) return m;
  }
  return nullptr;
}

const char* MotionMode::check(const HighLevelCommand& command) const {
  if (command.gait_id == kUserGaitId) {
    return user_gaits_.current() ? nullptr : "mode 62 gait 110: no user gait uploaded yet (user_gait_file)";
  }
  if (library_.find(command.gait_id) == nullptr) return "mode 62: no motion with this id (docs/motions.md)";
  return nullptr;
}

const char* MotionMode::check_step(const Motion& motion, const HighLevelCommand& step) const {
  const Mode* mode = step_mode(step.mode);
  if (mode == nullptr) return "a motion step runs mode 3, 11, 12 or 21";
  if (step.duration <= 0) return "a motion step needs duration > 0 (ms)";
  if (runs_user_gait(step)) {
    return motion.user_gait != nullptr ? nullptr : "a step of mode 11 gait 110 needs the motion's own user_gait files";
  }
  return mode->check(step);
}

std::size_t MotionMode::plan_size() const { return motion_ != nullptr ? motion_->steps.size() + 2 : 0; }

HighLevelCommand MotionMode::plan_step(std::size_t i) const {
  if (i == 0) return stand_up_step();
  if (i <= motion_->steps.size()) return motion_->steps[i - 1];
  // the stand pose: level, at the stand height, four feet down
  HighLevelCommand stand;
  stand.mode = static_cast<int>(kEndMode);
  stand.gait_id = kPoseAbsoluteHeightGait;
  stand.pos_des[2] = static_cast<float>(return_height_m_);
  stand.duration = config_.final_stand_ms;
  return stand;
}

void MotionMode::enter(const RobotState& state, const HighLevelCommand& command) {
  inner_ = nullptr;
  start(state, command);
}

void MotionMode::update(const RobotState& state, const HighLevelCommand& command) { start(state, command); }

void MotionMode::start(const RobotState& state, const HighLevelCommand& command) {
  motion_ = library_.find(command.gait_id);
  if (command.gait_id == kUserGaitId) {
    const std::shared_ptr<const UserGaitProgram> program = user_gaits_.current();
    if (program == nullptr) return;  // check() refuses such a command before it gets here
    user_gait_motion_.steps.front().duration = static_cast<std::int32_t>(std::ceil(program->duration_s() * 1e3));
    motion_ = &user_gait_motion_;
  }
  if (motion_ == nullptr) return;  // check() refuses such a command before it gets here
  stands_up_first_ = state.height_m < config_.standing_height_fraction * config_.stand_height_m;
  step_ = stands_up_first_ ? 0 : 1;
  return_height_m_ = config_.return_height_m.clamp(stands_up_first_ ? config_.stand_height_m : state.height_m);
  motion_start_s_ = last_time_s_ = state.time_s;
  planned_s_ = motion_->duration_s() + config_.final_stand_ms * 1e-3;
  running_ = true;
  begin_step(state);
}

void MotionMode::begin_step(const RobotState& state) {
  const HighLevelCommand step = plan_step(step_);
  // the motion's own gait, or (62/110) the uploaded one
  if (runs_user_gait(step) && motion_->user_gait != nullptr) user_gait_runner_.use_next(motion_->user_gait);
  Mode* next = step_mode(step.mode);
  if (next == nullptr) {
    running_ = false;  // load-time checks keep such steps out of the library
    return;
  }
  if (next == inner_) {
    next->update(state, step);
  } else {
    if (inner_ != nullptr) inner_->exit();
    inner_ = next;
    inner_->enter(state, step);
  }
  step_start_s_ = state.time_s;
  step_duration_s_ = step.duration * 1e-3;
}

void MotionMode::exit() {
  if (inner_ != nullptr) inner_->exit();
  inner_ = nullptr;
  running_ = false;
}

void MotionMode::run(const RobotState& state, JointCommand& command) {
  last_time_s_ = state.time_s;
  if (running_) {
    const double in_step_s = state.time_s - step_start_s_;
    const bool time_up = in_step_s >= step_duration_s_ - 1e-9;
    const bool settled =
        inner_->progress_percent() >= 100 || in_step_s >= step_duration_s_ + config_.step_overrun_limit_s;
    if (time_up && settled) {
      if (step_ == 0) motion_start_s_ = state.time_s;  // the motion starts once the robot stands
      if (++step_ < plan_size()) {
        begin_step(state);
      } else {
        running_ = false;  // the last step's mode holds the stand pose
      }
    }
  }
  if (inner_ != nullptr) inner_->run(state, command);
}

ContactPlan MotionMode::contact_plan() const { return inner_ != nullptr ? inner_->contact_plan() : std::nullopt; }

int MotionMode::progress_percent() const {
  if (!running_) return 100;
  if (step_ == 0 || planned_s_ <= 0.0) return 0;
  const double share = (last_time_s_ - motion_start_s_) / planned_s_;
  return std::clamp(static_cast<int>(std::floor(share * 100.0)), 0, 99);
}

}  // namespace cerebellum
