#include "modes/recovery_stand_mode.hpp"

#include <cmath>

namespace cerebellum {

RecoveryStandMode::RecoveryStandMode(const StandUpConfig& config, const SelfRightingConfig& righting)
    : stand_up_(config), righting_(righting) {}

const char* RecoveryStandMode::check(const HighLevelCommand& command) const {
  const int gait = command.gait_id;
  return gait == 0 || gait == kRollOverLeft || gait == kRollOverRight ? nullptr : "mode 12 accepts gait 0, 17 or 18";
}

void RecoveryStandMode::enter(const RobotState&, const HighLevelCommand& command) {
  gait_ = command.gait_id;
  phase_ = Phase::Assess;
  roll_attempts_ = 0;
}

void RecoveryStandMode::update(const RobotState& state, const HighLevelCommand& command) {
  if (command.gait_id != gait_) enter(state, command);
}

BodyRest RecoveryStandMode::roll_flank(BodyRest rest, const RobotState& state) const {
  BodyRest flank = BodyRest::OnRightSide;
  if (gait_ == kRollOverLeft) {
    flank = BodyRest::OnLeftSide;
  } else if (gait_ == kRollOverRight) {
    flank = BodyRest::OnRightSide;
  } else if (rest == BodyRest::OnLeftSide || rest == BodyRest::OnRightSide) {
    flank = rest;
  } else {
    // on the back: over the flank that is lower now
    const Eigen::Vector3d down = state.orientation.conjugate() * Eigen::Vector3d(0.0, 0.0, -1.0);
    flank = down.y() > 0.0 ? BodyRest::OnLeftSide : BodyRest::OnRightSide;
  }
  // a roll that did not make it is tried again over the other flank
  if (roll_attempts_ % 2 == 1) flank = flank == BodyRest::OnLeftSide ? BodyRest::OnRightSide : BodyRest::OnLeftSide;
  return flank;
}

void RecoveryStandMode::run(const RobotState& state, JointCommand& command) {
  // knocked over while rising (or still falling when the mode began): roll again
  if (phase_ == Phase::StandingUp && body_rest(state.orientation) != BodyRest::Upright) phase_ = Phase::Assess;
  if (phase_ == Phase::Assess) {
    const BodyRest rest = body_rest(state.orientation);
    if (rest == BodyRest::Upright) {
      stand_up_.restart();
      phase_ = Phase::StandingUp;
    } else {
      righting_.start(roll_flank(rest, state));
      ++roll_attempts_;
      phase_ = Phase::Righting;
    }
  }
  if (phase_ == Phase::Righting) {
    righting_.compute(state, command);
    // the last keyframe holds still: once it is done, look again
    if (righting_.done()) phase_ = Phase::Assess;
    return;
  }
  stand_up_.compute(state, command);
}

int RecoveryStandMode::progress_percent() const {
  switch (phase_) {
    case Phase::Assess: return 0;
    // a roll is the first half of the way, standing up the second
    case Phase::Righting: return static_cast<int>(std::floor(49.0 * righting_.progress()));
    case Phase::StandingUp: break;
  }
  const double stand = stand_up_.progress();
  if (roll_attempts_ > 0) return static_cast<int>(std::floor(50.0 + 50.0 * stand + 1e-9));
  return static_cast<int>(stand * 100.0 + 1e-9);
}

}  // namespace cerebellum
