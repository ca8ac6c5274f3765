// Mode 3: the force-based pose (QP stand). Gait 0 takes rpy_des / pos_des as absolute targets
// reached at the normal pose speed; gaits 1 and 3 move to the same targets in small increments
// (a slow ramp), so the hold command (3, 1) the queue inserts keeps the pose. Contact bits lift
// one leg while the robot balances on the other three.
#pragma once

#include "control/qp_stand.hpp"
#include "modes/command_ranges.hpp"
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

  const QpStand& stand() const { return stand_; }

 private:
  QpStandModeConfig config_;
  QpStand stand_;
  int gait_ = 0;
  bool timed_ = false;
};

// the goal a mode-3 command asks for, clamped to the ranges
QpStandGoal qp_stand_goal(const HighLevelCommand& command, const QpStandRanges& ranges,
                          const FootOffsetRanges& foot_offset);

}  // namespace cerebellum
