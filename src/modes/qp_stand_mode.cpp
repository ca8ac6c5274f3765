#include "modes/qp_stand_mode.hpp"

#include <cmath>

namespace cerebellum {

QpStandGoal qp_stand_goal(const CommandedPose& pose, const HighLevelCommand& command,
                          const FootOffsetRanges& foot_offset) {
  QpStandGoal goal;
  goal.pose.rpy = pose.body_rpy();
  goal.pose.position << pose.offset_m(), pose.height_m();
  goal.lifted_leg = lifted_leg_from_contact(command.contact);
  if (goal.lifted_leg >= 0) goal.lifted_foot_offset = lifted_foot_offset(command, goal.lifted_leg, foot_offset);
  return goal;
}

QpStandMode::QpStandMode(const QpStandModeConfig& config) : config_(config), stand_(config.stand) {}

const char* QpStandMode::check(const HighLevelCommand& command) const {
  if (command.gait_id != 0 && command.gait_id != 1 && command.gait_id != 3) {
    return "mode 3 accepts gait 0 (absolute) or 1, 3 (incremental)";
  }
  if (lifted_leg_from_contact(command.contact) == kInvalidContact) return "mode 3 lifts at most one leg (contact bits)";
  return nullptr;
}

void QpStandMode::enter(const RobotState& state, const HighLevelCommand& command) {
  stand_.start(state);
  pose_.reset(config_.ranges.default_height_m);
  update(state, command);
}

void QpStandMode::update(const RobotState&, const HighLevelCommand& command) {
  gait_ = command.gait_id;
  timed_ = command.duration > 0;
  const bool given_height = command.pos_des[2] > 0.0f;
  bool clamped = false;
  if (gait_ == 0) {
    clamped = pose_.set(command, given_height ? command.pos_des[2] : config_.ranges.default_height_m, config_.ranges);
  } else {
    clamped = pose_.add(command, given_height ? command.pos_des[2] - pose_.height_m() : 0.0, config_.ranges);
  }
  clamp_note_ = clamped ? "the pose would leave its range (docs/modes.md, mode 3): held at the range's edge" : nullptr;
  const QpStandGoal goal = qp_stand_goal(pose_, command, config_.foot_offset);
  const PoseSpeed& speed = gait_ == 0 ? config_.absolute_speed : config_.incremental_speed;
  // a timed command moves within its duration, never faster than the speed allows
  stand_.set_goal(goal, speed, timed_ ? command.duration * 1e-3 : 0.0);
}

void QpStandMode::run(const RobotState& state, JointCommand& command) { stand_.compute(state, command); }

int QpStandMode::progress_percent() const {
  // a timed entry's time runs while it moves (the queue pauses only for unfinished switches)
  if (timed_) return 100;
  return static_cast<int>(std::floor(stand_.progress() * 100.0));
}

}  // namespace cerebellum
