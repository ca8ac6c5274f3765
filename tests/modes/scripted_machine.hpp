// The high-level machine with scripted modes (they record what the machine asks of them), for
// the tests of the machine: switching, refusals, timeouts, the lease, floods.
#pragma once

#include "core/leg_kinematics.hpp"
#include "modes/high_level_machine.hpp"

namespace cerebellum::testing {

class ScriptedMode final : public Mode {
 public:
  ScriptedMode(ModeId id, int max_gait = 0) : id_(id), max_gait_(max_gait) {}
  ModeId id() const override { return id_; }
  const char* check(const HighLevelCommand& c) const override {
    return c.gait_id >= 0 && c.gait_id <= max_gait_ ? nullptr : "bad gait";
  }
  void enter(const RobotState&, const HighLevelCommand& c) override { gait_ = c.gait_id, ++entered; }
  void update(const RobotState&, const HighLevelCommand& c) override { gait_ = c.gait_id, ++updated; }
  void run(const RobotState&, JointCommand& command) override {
    command = JointCommand{};
    command.kp.fill(static_cast<double>(id_));
  }
  ContactPlan contact_plan() const override { return plan; }
  int gait_id() const override { return gait_; }
  int progress_percent() const override { return progress; }
  bool damping_protection() const override { return damping; }
  StartRefusal start_refusal(const RobotState&, const HighLevelCommand&) const override { return refusal; }
  void exit() override { ++exited; }
  bool must_finish() const override { return finishing; }

  ContactPlan plan;
  StartRefusal refusal;
  bool damping = false;
  bool finishing = false;
  int exited = 0;
  int progress = 100;
  int entered = 0;
  int updated = 0;

 private:
  ModeId id_;
  int max_gait_;
  int gait_ = 0;
};

inline HighLevelCommand cmd(ModeId mode, int gait, int life_count, int duration_ms = 0) {
  HighLevelCommand c;
  c.mode = static_cast<int>(mode);
  c.gait_id = gait;
  c.life_count = life_count;
  c.duration = duration_ms;
  return c;
}

struct Machine {
  explicit Machine(ModeId startup = ModeId::Off) : machine(0.002, cmd(startup, 0, 0)) {
    for (ScriptedMode* m : {&off, &damper, &recovery, &pose, &loco}) machine.add_mode(*m);
    state.valid = true;
    // feet where a standing robot has them, inside the walking workspace
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      state.foot_position_body[leg] = foot_position_in_body(leg, Vec3(0.0, 0.785, -1.22));
    }
  }
  // one tick at time t
  JointCommand tick() {
    JointCommand command;
    machine.compute(state, command);
    state.time_s += 0.002;
    return command;
  }
  ScriptedMode off{ModeId::Off}, damper{ModeId::PureDamper, 1}, recovery{ModeId::RecoveryStand},
      pose{ModeId::PoseControl, 5}, loco{ModeId::Locomotion, 31};
  HighLevelMachine machine;
  RobotState state;
};

}  // namespace cerebellum::testing
