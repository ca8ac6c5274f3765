#include "modes/locomotion_mode.hpp"

namespace cerebellum {

const char* unavailable_gait_reason(int gait_id) {
  switch (gait_id) {
    case 1: return "gait 1 (stand) not available yet";
    case 2: return "gait 2 (pronk) not available yet";
    case 3: return "gait 3 (medium trot) not available yet";
    case 4: return "gait 4 (walk-dog trot) not available yet";
    case 7: return "gait 7 (bound) not available yet";
    case 10: return "gait 10 (flying trot) not available yet";
    case 26: return "gait 26 (variable-frequency trot) not available yet";
    case 27: return "gait 27 (slow trot) not available yet";
    case 31: return "gait 31 (stand without push recovery) not available yet";
    case 110: return "gait 110 (uploaded user gait) not available yet";
    default:
      if (gait_id >= 80 && gait_id <= 100) return "user gait slots 80..100 not available yet";
      return "mode 11 has no such gait";
  }
}

LocomotionMode::LocomotionMode(const GaitRegistry& gaits, const LocomotionStandRanges& ranges)
    : gaits_(gaits), ranges_(ranges) {}

LocomotionCommand LocomotionMode::clamped(const HighLevelCommand& command) const {
  LocomotionCommand c;
  c.gait_id = command.gait_id;
  if (const VelocityLimits* limits = locomotion_velocity_limits(command.gait_id)) {
    const Eigen::Vector3d wanted(command.vel_des[0], command.vel_des[1], command.vel_des[2]);
    c.velocity = wanted.cwiseMax(limits->min).cwiseMin(limits->max);
  }
  c.pitch_rad = ranges_.pitch.clamp(command.rpy_des[1]);
  c.height_m = command.pos_des[2] > 0.0f ? ranges_.height.clamp(command.pos_des[2]) : ranges_.default_height_m;
  c.step_height_m = {kStepHeightRange.clamp(command.step_height[0]), kStepHeightRange.clamp(command.step_height[1])};
  c.value = command.value;
  c.duration_ms = command.duration;
  c.raw = command;
  return c;
}

const char* LocomotionMode::check(const HighLevelCommand& command) const {
  const LocomotionGait* gait = gaits_.find(command.gait_id);
  if (gait == nullptr) return unavailable_gait_reason(command.gait_id);
  return gait->check(command);
}

void LocomotionMode::enter(const RobotState& state, const HighLevelCommand& command) {
  running_ = gaits_.find(command.gait_id);
  gait_id_ = command.gait_id;
  running_->start(state, clamped(command));
}

void LocomotionMode::update(const RobotState& state, const HighLevelCommand& command) {
  LocomotionGait* next = gaits_.find(command.gait_id);
  gait_id_ = command.gait_id;
  // the same gait object (same gait, or stand 1 <-> 31) keeps running; another one takes over
  if (next == running_) {
    running_->update(clamped(command));
    return;
  }
  running_->stop();
  running_ = next;
  running_->start(state, clamped(command));
}

void LocomotionMode::exit() {
  if (running_ != nullptr) running_->stop();
}

void LocomotionMode::run(const RobotState& state, JointCommand& command) { running_->run(state, command); }

ContactPlan LocomotionMode::contact_plan() const {
  return running_ != nullptr ? running_->contact_plan() : std::nullopt;
}

int LocomotionMode::progress_percent() const { return running_->progress_percent(); }

}  // namespace cerebellum
