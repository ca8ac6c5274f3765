// Mode 16, Jump3D: the reference's one-shot jumps by gait id (turns, leaps, hops, up, down a
// stair), planned by the MC from the robot's stand when the command arrives and run by
// JumpController. The response shows 16 with the jump id and the share of crouch, push, flight
// and landing done; afterwards the robot stands in the mode until the next command. A jump that
// cannot land damps the joints (EDAMP) for the recovery stand.
#pragma once

#include <array>

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
    // the stair's height is not known before touchdown: planned for a 10 cm step, landed when the
    // feet find the ground
    {9, "down a stair", 0.3, 0.0, 0.0, 0.0, -0.1},
}};

// the entry of a jump id, or nullptr
const JumpSpec* find_jump(int gait_id);
JumpTarget jump_target(const JumpSpec& spec);

class JumpMode final : public Mode {
 public:
  explicit JumpMode(const JumpControllerConfig& config);
  ModeId id() const override { return ModeId::Jump3d; }
  const char* check(const HighLevelCommand& command) const override;
  const char* start_refusal(const RobotState& state) const override;
  void enter(const RobotState& state, const HighLevelCommand& command) override;
  void update(const RobotState& state, const HighLevelCommand& command) override;
  void run(const RobotState& state, JointCommand& command) override;
  int gait_id() const override { return gait_; }
  int progress_percent() const override;
  bool holds_entry() const override { return !controller_.finished(); }
  bool damping_protection() const override { return controller_.failed(); }
  bool airborne() const override { return !controller_.finished(); }

  const JumpController& controller() const { return controller_; }

 private:
  JumpController controller_;
  int gait_ = 0;
};

}  // namespace cerebellum
