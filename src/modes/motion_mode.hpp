// Mode 62: runs a named motion, a list of timed steps of other modes (pose control, QP stand,
// locomotion, recovery stand), through those modes themselves. A robot that is not standing
// stands up first (recovery stand); after the last step it returns to a level stand at the height
// it stood at when the motion started, its centre of mass over its feet, and reports 100. The response shows mode 62
// with gait_id = the motion id and the share of the motion done.
#pragma once

#include <array>
#include <cstddef>

#include "modes/command_ranges.hpp"
#include "modes/mode.hpp"
#include "modes/motion.hpp"
#include "modes/user_gait.hpp"
#include "modes/user_gait_runner.hpp"

namespace cerebellum {

struct MotionModeConfig {
  double stand_height_m = kDefaultBodyHeightM;  // after a stand-up
  Range return_height_m = PoseControlRanges{}.height;
  // below this share of the stand height the robot stands up before the motion
  double standing_height_fraction = 0.8;
  int final_stand_ms = 800;  // back to the stand pose after the last step
  // a step's mode that has not finished its move this long after the step's time is left behind
  double step_overrun_limit_s = 3.0;
};

class MotionMode final : public Mode {
 public:
  // the mode of the motion's last step, the level stand: a finished motion leaves the robot in it
  static constexpr ModeId kEndMode = ModeId::PoseControl;

  // the modes a step may run, by mode id; the library must outlive this mode
  using StepModes = std::array<Mode*, 4>;
  // user_gait_runner: where a motion's own user gait is handed to its 11/110 steps
  MotionMode(const MotionLibrary& library, const StepModes& step_modes, const UserGaitSlot& user_gaits,
             UserGaitRunner& user_gait_runner, const MotionModeConfig& config = {});

  ModeId id() const override { return ModeId::Motion; }
  const char* check(const HighLevelCommand& command) const override;
  void enter(const RobotState& state, const HighLevelCommand& command) override;
  void exit() override;
  void update(const RobotState& state, const HighLevelCommand& command) override;
  void run(const RobotState& state, JointCommand& command) override;
  ContactPlan contact_plan() const override;
  int gait_id() const override { return motion_ != nullptr ? motion_->id : 0; }
  int progress_percent() const override;
  // the queue entry of a 62 command lasts at least until the motion ends
  bool holds_entry() const override { return running_; }
  // a step's mode that damps (its walking gave up) makes the motion report it
  bool damping_protection() const override { return inner_ != nullptr && inner_->damping_protection(); }

  // nullptr when a step may run in the motion (its mode is a step mode and accepts it; an 11/110
  // step needs the motion's own user gait), else why not
  const char* check_step(const Motion& motion, const HighLevelCommand& step) const;
  const MotionLibrary& library() const { return library_; }

 private:
  Mode* step_mode(int mode) const;
  // the step at plan position i: the stand-up, the motion's steps, the final stand
  HighLevelCommand plan_step(std::size_t i) const;
  std::size_t plan_size() const;
  void start(const RobotState& state, const HighLevelCommand& command);
  void begin_step(const RobotState& state);

  const MotionLibrary& library_;
  StepModes step_modes_;
  const UserGaitSlot& user_gaits_;
  UserGaitRunner& user_gait_runner_;
  Motion user_gait_motion_;  // 62/110: one step of 11/110 as long as the uploaded gait
  MotionModeConfig config_;
  const Motion* motion_ = nullptr;
  Mode* inner_ = nullptr;
  bool stands_up_first_ = false;
  double return_height_m_ = 0.0;  // the final stand's height
  std::size_t step_ = 0;          // plan position
  double step_start_s_ = 0.0;
  double step_duration_s_ = 0.0;
  double motion_start_s_ = 0.0;
  double planned_s_ = 0.0;
  double last_time_s_ = 0.0;
  bool running_ = false;
};

}  // namespace cerebellum
