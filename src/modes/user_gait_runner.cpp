#include "modes/user_gait_runner.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "control/locomotion/gait_table.hpp"

namespace cerebellum {
namespace {

// the user gait's pattern while its schedule plays: every leg down (the schedule is the
// sequence's), the velocity limits of the variable-frequency trot, the widest of the table
GaitPattern user_gait_pattern() {
  GaitPattern pattern = *gait_pattern(kStandGaitId);
  const GaitSpec& widest = *find_gait(kVariableTrotGaitId);
  pattern.id = kUserGaitId;
  pattern.velocity_min = widest.velocity_min;
  pattern.velocity_max = widest.velocity_max;
  return pattern;
}

}  // namespace

UserGaitRunner::UserGaitRunner(WalkingGaits& walking, const UserGaitSlot& slot) : walking_(walking), slot_(slot) {}

const char* UserGaitRunner::check(const HighLevelCommand&) const {
  if (!slot_.current()) return "no user gait uploaded yet (user_gait_file: a definition and its parameters)";
  return nullptr;
}

void UserGaitRunner::start(const RobotState& state, const LocomotionCommand& command) {
  program_ = next_ != nullptr ? std::exchange(next_, nullptr) : slot_.current();
  LocomotionCommand stand = command;
  stand.gait_id = kStandGaitId;
  stand.velocity.setZero();
  walking_.start(state, stand);
  start_s_ = state.time_s;
  elapsed_s_ = 0.0;
  finished_ = program_ == nullptr;
  if (finished_) return;
  total_s_ = program_->duration_s();
  walking_.play(program_->sequence, state);
  step_ = 0;
  step_end_s_ = program_->steps.empty() ? 0.0 : program_->steps.front().duration_s;
  steer_to_step(0);
}

void UserGaitRunner::steer_to_step(std::size_t index) {
  LocomotionTarget target;
  target.gait = user_gait_pattern();
  target.vertical_legs = true;  // landing offsets are from under the hips
  if (index < program_->steps.size()) {
    const UserGaitStep& step = program_->steps[index];
    target.velocity = step.body_velocity();
    target.pitch_rad = step.pitch_rad;
    target.height_m = step.height_m;
    target.user_step = step.legs;
  } else if (!program_->steps.empty()) {
    // the schedule outlasts the steps: the last step's pose and feet, the body at rest
    const UserGaitStep& last = program_->steps.back();
    target.pitch_rad = last.pitch_rad;
    target.height_m = last.height_m;
    target.user_step = last.legs;
  }
  walking_.steer(target);
}

void UserGaitRunner::run(const RobotState& state, JointCommand& command) {
  if (program_ != nullptr && !finished_) {
    elapsed_s_ = state.time_s - start_s_;
    while (step_ < program_->steps.size() && elapsed_s_ >= step_end_s_ - 1e-9) {
      ++step_;
      if (step_ < program_->steps.size()) step_end_s_ += program_->steps[step_].duration_s;
      steer_to_step(step_);
    }
    if (elapsed_s_ >= total_s_ - 1e-9) {
      // done: the stand gait on the same controller, where the robot is
      finished_ = true;
      LocomotionTarget stand;
      stand.gait = *gait_pattern(kStandGaitId);
      stand.height_m = program_->steps.empty() ? kDefaultBodyHeightM : program_->steps.back().height_m;
      walking_.steer(stand);
    }
  }
  walking_.run(state, command);
}

void UserGaitRunner::stop() { walking_.stop(); }

int UserGaitRunner::progress_percent() const {
  if (finished_ || program_ == nullptr) return 100;
  if (total_s_ <= 0.0) return 100;
  return std::clamp(static_cast<int>(std::floor(100.0 * elapsed_s_ / total_s_)), 0, 99);
}

}  // namespace cerebellum
