// One behaviour of the high-level state machine (a row of the mode table).
#pragma once

#include "core/contact_plan.hpp"
#include "core/robot_state.hpp"
#include "core/types.hpp"
#include "core/high_level_command.hpp"

namespace cerebellum {

// a command the robot's state refuses: the status the response shows and the reason logged
struct StartRefusal {
  SwitchStatus status = SwitchStatus::BanTransition;
  const char* reason = nullptr;  // static string; nullptr: not refused
  explicit operator bool() const { return reason != nullptr; }
};

class Mode {
 public:
  virtual ~Mode() = default;
  virtual ModeId id() const = 0;
  // nullptr when the command's gait and values suit this mode, else why it is refused
  virtual const char* check(const HighLevelCommand& command) const = 0;
  // why the robot's state does not let the command start the mode (or take effect in it) now:
  // a jump needs a still, level stand, a flip cool motors and charge (safety/jump_gate); no
  // reason: it may
  virtual StartRefusal start_refusal(const RobotState&, const HighLevelCommand&) const { return {}; }
  // the mode takes over the robot
  virtual void enter(const RobotState& state, const HighLevelCommand& command) = 0;
  // another mode takes over the robot
  virtual void exit() {}
  // a new command while this mode runs (same mode id, maybe another gait or target)
  virtual void update(const RobotState& state, const HighLevelCommand& command) = 0;
  // why the command of the last enter() / update() was clamped (a static string, the client's
  // log says it), or nullptr when it was taken as sent
  virtual const char* clamp_note() const { return nullptr; }
  // one control tick; must not block, allocate or print
  virtual void run(const RobotState& state, JointCommand& command) = 0;
  // the contacts the last run() planned for the next tick (for the estimator); none unless it steps
  virtual ContactPlan contact_plan() const { return std::nullopt; }
  virtual int gait_id() const = 0;
  // order_process_bar: percent of the mode's transition done; 100 once it holds its target
  virtual int progress_percent() const = 0;
  // true while the command queue must keep the mode's entry running past its duration (a motion
  // runs to its end); the entry's time still counts meanwhile
  virtual bool holds_entry() const { return false; }
  // true while the mode has given up its task and damps the joints so that the robot sinks down
  // (a walking gait whose MPC keeps failing): switch_status 3, EDAMP
  virtual bool damping_protection() const { return false; }
  // true while the mode leaves the ground on purpose (a jump): feet without load are no lift
  virtual bool airborne() const { return false; }
  // true while the mode turns the body over on purpose (a flip): the body watch's orientation and
  // foot checks would read it as a fall; its own landing check takes over once it is down
  virtual bool turns_over() const { return false; }
  // true while ending the mode now would drop the robot (a jump in the air, a two-leg stand off
  // its front feet): the get-down protection of a silent client waits until it is back on its
  // feet, and a client's command of another mode is refused meanwhile, except damping and off
  virtual bool must_finish() const { return airborne(); }
};

}  // namespace cerebellum
