#include "modes/mode_switcher.hpp"

#include "modes/transition_table.hpp"

namespace cerebellum {

Mode* ModeSwitcher::find(int mode) const {
  if (mode < 0 || mode >= static_cast<int>(modes_.size())) return nullptr;
  return modes_[static_cast<std::size_t>(mode)];
}

StartRefusal ModeSwitcher::switch_refusal(const Mode& target, const RobotState& state,
                                          const HighLevelCommand& command) const {
  if (&target != current_ && !transition_allowed(current_->id(), target.id())) {
    return {SwitchStatus::BanTransition, "transition not allowed from the current mode"};
  }
  if (&target != current_ && current_->must_finish() && target.id() != ModeId::PureDamper &&
      target.id() != ModeId::Off) {
    return {SwitchStatus::BanTransition, "the robot is not back on its feet yet (damping and off still stop it)"};
  }
  return target.start_refusal(state, command);
}

void ModeSwitcher::switch_to(Mode& target, const RobotState& state, const HighLevelCommand& command) {
  if (current_ != nullptr && current_ != &target) current_->exit();
  current_ = &target;
  running_command_ = command;
  target.enter(state, command);
}

void ModeSwitcher::update(const RobotState& state, const HighLevelCommand& command) {
  running_command_ = command;
  current_->update(state, command);
}

}  // namespace cerebellum
