// Mode 3: the force-based pose (QP stand). Gait 0 takes rpy_des / pos_des x, y as an absolute
// pose reached at the normal pose speed; gaits 1 and 3 are incremental (the reference): rpy_des and
// pos_des x, y move the pose from where the previous command left it, at the slower speed, so the
// hold command (3, 1, no increment) the queue inserts keeps the pose. The height pos_des[2] is
// absolute in every gait (0: gait 0 the default, gaits 1, 3 unchanged). The pose starts as the
// level stand on entry; a sum outside the ranges is held at their edge and reported. Contact bits
// lift one leg while the robot balances on the other three. +pitch raises the head (commanded_pose).
#pragma once

#include "control/qp_stand.hpp"
#include "modes/command_ranges.hpp"
#include "modes/commanded_pose.hpp"
#include "modes/mode.hpp"

namespace cerebellum {

// mode 3's gait that moves to its target in small increments (what a held force pose runs)
inline constexpr int kQpStandIncrementalGait = 1;

struct QpStandModeConfig {
  QpStandConfig stand;
  QpStandRanges ranges;
  FootOffsetRanges foot_offset;
  PoseSpeed absolute_speed{0.8, 0.15, 0.3};
  PoseSpeed incremental_speed{0.3, 0.05, 0.3};
};

class QpStandMode final : public Mode {
 public:
  explicit QpStandMode(const QpStandModeConfig& config = {});
  ModeId id() const override { return ModeId::QpStand; }
  const char* check(const HighLevelCommand& command) const override;
  void enter(const RobotState& state, const HighLevelCommand& command) override;
  void update(const RobotState& state, const HighLevelCommand& command) override;
  void run(const RobotState& state, JointCommand& command) override;
  int gait_id() const override { return gait_; }
  int progress_percent() const override;
  const char* clamp_note() const override { return clamp_note_; }

  const QpStand& stand() const { return stand_; }

 private:
  QpStandModeConfig config_;
  QpStand stand_;
  int gait_ = 0;
  bool timed_ = false;
  CommandedPose pose_;  // what the commands asked for so far
  const char* clamp_note_ = nullptr;
};

// the goal of the commanded pose, with the command's lifted leg and its foot offset
QpStandGoal qp_stand_goal(const CommandedPose& pose, const HighLevelCommand& command,
                          const FootOffsetRanges& foot_offset);

}  // namespace cerebellum
