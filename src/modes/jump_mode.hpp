// The jump modes, planned by the MC from the robot's stand when the command arrives and run by
// JumpController: mode 16, Jump3D, the reference's one-shot jumps by gait id (turns, leaps, hops,
// up, down a stair); mode 22, the force jump, from the take-off accelerations in acc_des. The
// response shows the mode with the jump id and the share of crouch, push, flight and landing
// done; afterwards the robot stands in the mode until the next command. A jump that cannot land
// damps the joints (EDAMP) for the recovery stand.
#pragma once

#include <array>

#include <optional>

#include "control/jump/flip_run.hpp"
#include "control/jump/flip_trajectory.hpp"
#include "control/jump/jump_controller.hpp"
#include "modes/mode.hpp"

namespace cerebellum {

// one jump of the mode-16 table (cyberdog2-highlevel.md section 4): the target as the reference
// names it, in the robot's heading frame at take-off
struct JumpSpec {
  int gait_id;
  const char* name;
  double forward_m;
  double left_m;
  double turn_deg;  // counter-clockwise
  double apex_rise_m;
  double landing_ground_m;  // below the take-off ground: negative
};

inline constexpr std::array<JumpSpec, 8> kJump3dTable{{
    {0, "left 90 deg", 0.0, 0.0, 90.0, 0.0, 0.0},
    {1, "forward 60 cm", 0.6, 0.0, 0.0, 0.0, 0.0},
    {2, "left 20 cm", 0.0, 0.2, 0.0, 0.0, 0.0},
    {3, "right 90 deg", 0.0, 0.0, -90.0, 0.0, 0.0},
    {4, "forward 30 cm", 0.3, 0.0, 0.0, 0.0, 0.0},
    {5, "right 20 cm", 0.0, -0.2, 0.0, 0.0, 0.0},
    {6, "up 30 cm", 0.0, 0.0, 0.0, 0.3, 0.0},
    // from the edge of a step (front feet at it) far enough that the rear feet clear it too; its
    // height is not known before touchdown: planned for 10 cm, landed when the feet find the ground
    {9, "down a stair", 0.6, 0.0, 0.0, 0.0, -0.1},
}};

// flips, this MC's documented extension of the mode-16 ids (the reference's table has no id for
// them): refused with OVER_HEAT / LOW_BAT as the reference says; each plays its planned file
// (config/flips/back_flip.csv, front_flip.csv) from a still stand and lands as a jump lands; a
// flip without a file is refused with BAN_TRANS (docs/jumps.md)
inline constexpr int kBackFlipGaitId = 20;
inline constexpr int kFrontFlipGaitId = 21;

// the flips' plans the MC read at start (none: that flip is refused)
struct FlipPlans {
  std::optional<FlipTrajectory> back;
  std::optional<FlipTrajectory> front;
};

// the entry of a jump id, or nullptr
const JumpSpec* find_jump(int gait_id);
JumpTarget jump_target(const JumpSpec& spec);

// mode 22's acc_des: [0..2] the robot's (centre of mass's) acceleration during the push (m/s^2;
// forward, left, up; gravity not included), [5] its yaw acceleration (rad/s^2); [3], [4] (roll, pitch) are
// not used: a jump lands level
JumpPlan force_jump_plan(const HighLevelCommand& command, const JumpLimits& limits);

class JumpMode final : public Mode {
 public:
  // mode: ModeId::Jump3d or ModeId::ForceJump; flips: the flips' plans, if any
  JumpMode(ModeId mode, const JumpControllerConfig& config, FlipPlans flips = {});
  ModeId id() const override { return mode_; }
  const char* check(const HighLevelCommand& command) const override;
  StartRefusal start_refusal(const RobotState& state, const HighLevelCommand& command) const override;
  void enter(const RobotState& state, const HighLevelCommand& command) override;
  void update(const RobotState& state, const HighLevelCommand& command) override;
  void run(const RobotState& state, JointCommand& command) override;
  int gait_id() const override { return gait_; }
  int progress_percent() const override;
  bool holds_entry() const override { return flipping() || !controller_.finished(); }
  bool damping_protection() const override { return !flipping() && controller_.failed(); }
  bool airborne() const override { return flipping() || !controller_.finished(); }
  bool turns_over() const override { return flip_.turning_over(); }
  // in flight no foot is on the ground: the legs swinging to the landing pose load their joints
  // as if their feet pushed, and the estimator, judging contacts from those forces, took them
  // for stance feet; otherwise nothing is planned (the force estimate judges the contacts)
  ContactPlan contact_plan() const override;

  const JumpController& controller() const { return controller_; }

 private:
  // a played flip before its landing (the controller lands it)
  bool flipping() const { return flip_.stage() != FlipStage::Idle && !flip_.done(); }
  // the plan of a flip id, or nullptr (not a flip, or no file)
  const FlipTrajectory* flip_plan(int gait_id) const;

  ModeId mode_;
  JumpController controller_;
  FlipPlans flips_;
  FlipRun flip_;
  double flip_time_s_ = 0.0;  // the newest tick's time while flipping (for the progress bar)
  int gait_ = 0;
};

}  // namespace cerebellum
