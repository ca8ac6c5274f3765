#include "modes/recovery_stand_mode.hpp"

namespace cerebellum {

RecoveryStandMode::RecoveryStandMode(const StandUpConfig& config) : stand_up_(config) {}

const char* RecoveryStandMode::check(const HighLevelCommand& command) const {
  return command.gait_id == 0 ? nullptr : "mode 12 accepts gait 0";
}

void RecoveryStandMode::enter(const RobotState&, const HighLevelCommand& command) {
  gait_ = command.gait_id;
  stand_up_.restart();
}

void RecoveryStandMode::update(const RobotState&, const HighLevelCommand&) {}

void RecoveryStandMode::run(const RobotState& state, JointCommand& command) { stand_up_.compute(state, command); }

int RecoveryStandMode::progress_percent() const { return static_cast<int>(stand_up_.progress() * 100.0 + 1e-9); }

}  // namespace cerebellum
