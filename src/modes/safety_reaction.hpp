// The machine's reaction to what safety/ reports: the health protection (damp, then motors off),
// the body watch of the standing modes (tipped over or a foot out of reach -> PureDamper, latched
// until a recovery stand; picked up -> Lifted, and back once set down). safety/ decides what is
// wrong; this says which mode that calls for and which commands are refused meanwhile. The machine
// does the switching.
#pragma once

#include <optional>

#include "core/high_level_command.hpp"
#include "core/robot_state.hpp"
#include "modes/mode_switcher.hpp"
#include "safety/health_monitor.hpp"
#include "safety/lift_detector.hpp"

namespace cerebellum {

// what the body watch calls for this tick
struct BodyReaction {
  enum class Action {
    None,
    Damp,  // a body fault: damp the joints and drop the client's sequence
    Lift,  // picked up: the Lifted mode
    Land,  // set down: back to the command the robot was lifted in
  };
  Action action = Action::None;
  HighLevelCommand command;  // the command to switch with (not for None)
};

class SafetyReaction {
 public:
  // the health protection of this tick (acted on in the tick; reported at once)
  void observe_health(const HealthVerdict& verdict) { health_ = verdict; }
  const HealthVerdict& health() const { return health_; }
  // the mode the health protection calls for now: PureDamper while it damps, Off once it stopped
  // the motors; none without a protection or when the running mode already is it (or Off)
  std::optional<ModeId> health_target(ModeId current) const;

  // why a command switching to (or updating) target is refused now, or nullptr: a health
  // protection, a latched body fault (only a recovery stand, damping or off), or a lifted robot
  const char* refusal(ModeId target, ModeId current) const;

  // after the tick's commands: the body watch of the running mode (switcher.find tells which of
  // PureDamper and Lifted this MC runs); a Damp latches the fault until a recovery stand
  BodyReaction watch_body(const RobotState& state, const ModeSwitcher& switcher);

  // a mode switch took place: the lift watch starts afresh; a recovery stand clears the latch
  void on_switch(ModeId entered);

  // the latched body faults (ori_error, footpos_error of the response)
  bool orientation_error() const { return orientation_error_; }
  int foot_position_error() const { return foot_position_error_; }
  // what the response's switch_status must say for the protections, or none: EDAMP while the
  // health protection damps, ESTOP once it stopped the motors (health only: reported at once)
  std::optional<SwitchStatus> health_status() const;
  // the same with the latched body faults (ESTOP for a tipped-over robot, EDAMP for a foot)
  std::optional<SwitchStatus> protection_status() const;

 private:
  LiftDetectorConfig lift_config_;
  LiftWatch lift_watch_;             // the lift decision's memory, reset on every mode switch
  HighLevelCommand resume_command_;  // where a lifted robot goes once set down
  bool orientation_error_ = false;   // latched until a recovery stand starts
  int foot_position_error_ = 0;      // footpos_error bits, latched likewise
  HealthVerdict health_;
};

}  // namespace cerebellum
