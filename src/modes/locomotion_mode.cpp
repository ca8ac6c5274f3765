#include "modes/locomotion_mode.hpp"

#include "modes/commanded_pose.hpp"

#include <array>
#include <string>

#include "control/locomotion/gait_table.hpp"

namespace cerebellum {
namespace {

// "gait N (name) not available yet" for every gait of the table, built before the loop runs
std::array<std::string, kGaitTable.size()> unavailable_reasons() {
  std::array<std::string, kGaitTable.size()> all;
  for (std::size_t i = 0; i < kGaitTable.size(); ++i) {
    all[i] = "gait " + std::to_string(kGaitTable[i].id) + " (" + kGaitTable[i].name + ") not available yet";
  }
  return all;
}
const std::array<std::string, kGaitTable.size()> kUnavailableReasons = unavailable_reasons();

}  // namespace

const char* unavailable_gait_reason(int gait_id) {
  if (const GaitSpec* gait = find_gait(gait_id)) {
    return kUnavailableReasons[static_cast<std::size_t>(gait - kGaitTable.data())].c_str();
  }
  if (gait_id == kUserGaitId) return "gait 110 (uploaded user gait) not available in this MC";
  if (gait_id >= 80 && gait_id <= 100) return "user gait slots 80..100 not available yet";
  return "mode 11 has no such gait";
}

LocomotionMode::LocomotionMode(const GaitRegistry& gaits, const LocomotionLimits& limits,
                               const LocomotionStandRanges& ranges)
    : gaits_(gaits), limits_(limits), ranges_(ranges) {}

LocomotionCommand LocomotionMode::clamped(const HighLevelCommand& command) const {
  LocomotionCommand c;
  c.gait_id = command.gait_id;
  if (const VelocityLimits* limits = limits_.velocity(command.gait_id)) {
    const Eigen::Vector3d wanted(command.vel_des[0], command.vel_des[1], command.vel_des[2]);
    c.velocity = wanted.cwiseMax(limits->min).cwiseMin(limits->max);
    c.velocity_limits = *limits;
  }
  c.pitch_rad = body_pitch_from_command(ranges_.pitch.clamp(command.rpy_des[1]));
  c.height_m = command.pos_des[2] > 0.0f ? ranges_.height.clamp(command.pos_des[2]) : ranges_.default_height_m;
  c.step_height_m = {limits_.step_height().clamp(command.step_height[0]), limits_.step_height().clamp(command.step_height[1])};
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
  if (next->walking_controller() == running_->walking_controller()) {
    running_ = next;
    running_->take_over(state, clamped(command));
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
