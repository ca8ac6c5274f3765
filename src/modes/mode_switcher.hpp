// Which mode runs, and whether a command may change it: the modes registered by id, the running
// one and the command it was entered or last updated with. The machine asks it in the order the
// refusals are reported (the command's values, then the protections, then the switch itself).
#pragma once

#include <array>

#include "core/high_level_command.hpp"
#include "core/robot_state.hpp"
#include "modes/mode.hpp"

namespace cerebellum {

class ModeSwitcher {
 public:
  // before the loop starts
  void add(Mode& mode) { modes_[static_cast<std::size_t>(mode.id())] = &mode; }

  // the registered mode of this id, or nullptr (an unknown id or a mode this MC does not run)
  Mode* find(int mode) const;
  Mode* find(ModeId mode) const { return find(static_cast<int>(mode)); }
  bool started() const { return current_ != nullptr; }
  // only once started()
  Mode& current() const { return *current_; }
  ModeId current_id() const { return current_->id(); }
  // the running mode's id, or -1 before the start (what a refusal note reports as "while in")
  int current_mode() const { return started() ? static_cast<int>(current_id()) : -1; }
  // the command the running mode was entered or last updated with
  const HighLevelCommand& running_command() const { return running_command_; }

  // why the command's own values do not suit its mode, or nullptr
  static const char* command_refusal(const Mode& target, const HighLevelCommand& command) {
    return target.check(command);
  }
  // why the running mode may not give way to target for this command now: the transition table,
  // a mode that must finish first, the robot's state (Mode::start_refusal); no reason: it may
  StartRefusal switch_refusal(const Mode& target, const RobotState& state, const HighLevelCommand& command) const;

  // the running mode exits (when it is another) and target enters with the command
  void switch_to(Mode& target, const RobotState& state, const HighLevelCommand& command);
  // a new command for the running mode
  void update(const RobotState& state, const HighLevelCommand& command);

 private:
  std::array<Mode*, kMaxModeId + 1> modes_{};
  Mode* current_ = nullptr;
  HighLevelCommand running_command_;
};

}  // namespace cerebellum
