#include "modes/two_leg_stand_mode.hpp"

#include <cmath>

namespace cerebellum {

TwoLegStandMode::TwoLegStandMode(const TwoLegStandConfig& config) : controller_(config) {}

const char* TwoLegStandMode::check(const HighLevelCommand& command) const {
  return command.gait_id == 0 ? nullptr : "mode 64 (two-leg stand) has gait_id 0 only";
}

StartRefusal TwoLegStandMode::start_refusal(const RobotState&, const HighLevelCommand&) const {
  // a running two-leg stand ignores new commands of its mode (one-shot): nothing to refuse
  if (!controller_.finished()) return {};
  if (!controller_.design_error().empty()) {
    return {SwitchStatus::BanTransition,
            "two-leg stand not available: its balance could not be designed on the robot model"};
  }
  return {};
}

void TwoLegStandMode::enter(const RobotState& state, const HighLevelCommand& command) {
  controller_.start(state, 1e-3 * command.duration);
}

void TwoLegStandMode::update(const RobotState& state, const HighLevelCommand& command) {
  if (controller_.finished()) enter(state, command);
}

int TwoLegStandMode::progress_percent() const { return static_cast<int>(std::floor(controller_.progress() * 100.0)); }

bool TwoLegStandMode::must_finish() const {
  switch (controller_.phase()) {
    case TwoLegPhase::Rise:
    case TwoLegPhase::Hold:
    case TwoLegPhase::Lower:
    case TwoLegPhase::FrontDown: return true;
    default: return false;
  }
}

}  // namespace cerebellum
