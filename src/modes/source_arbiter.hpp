// Decides which client interface commands the robot: one source at a time.
// The MC's own behaviour (stand-up, passive, later the high-level state machine) runs until a
// low-level source asks for control while the MC is in a state that allows it; that source is
// then latched until restart, like the vendor's motor mode. Other sources asking afterwards are
// refused and counted.
#pragma once

#include <cstdint>
#include <vector>

#include "control/motion_controller.hpp"

namespace cerebellum {

// a low-level client interface (motor SDK over LCM, shared memory) seen from the loop thread
class LowLevelSource : public MotionController {
 public:
  virtual const char* name() const = 0;
  // true when the client has sent a command and wants the motors (checked every tick)
  virtual bool wants_control() const = 0;
  // the arbiter gave this source the robot
  virtual void on_latched(const RobotState& state) = 0;
  // the arbiter refused this source: another one has the robot, or the MC's state forbids it
  virtual void on_refused(const char* holder) = 0;
};

// the MC's own behaviour, which may or may not hand over to a low-level source right now
class OwnBehaviour : public MotionController {
 public:
  // only from Off or PureDamper, as on the vendor's MC
  virtual bool allows_low_level_latch() const = 0;
  // a low-level source has taken the robot until restart
  virtual void on_handover() {}
  // every tick while a low-level source holds the robot: the MC's own behaviour commands nothing
  // but keeps taking its clients' input (to refuse it) and reporting the live state
  virtual void observe_while_held(const RobotState& /*state*/, const char* /*holder*/) {}
};

class SourceArbiter final : public MotionController {
 public:
  explicit SourceArbiter(OwnBehaviour& own);
  void add_low_level_source(LowLevelSource& source);
  void compute(const RobotState& state, JointCommand& command) override;
  // the MC's own behaviour reports the protection whoever holds the robot
  void observe_health(const HealthVerdict& verdict) override { own_.observe_health(verdict); }
  // the plan of whoever computed the command: the latched source or the MC's own behaviour
  ContactPlan contact_plan() const override;
  // the MC's own behaviour reports the high-level state whoever holds the robot
  void report(HighLevelReport& report) const override { own_.report(report); }

  // the latched source, or nullptr while the MC's own behaviour runs
  const LowLevelSource* latched() const { return latched_; }
  std::uint64_t refusals() const { return refusals_; }

 private:
  OwnBehaviour& own_;
  std::vector<LowLevelSource*> sources_;
  LowLevelSource* latched_ = nullptr;
  std::uint64_t refusals_ = 0;
};

}  // namespace cerebellum
