// Mode 11: locomotion. The gait_id picks a LocomotionGait from the registry; commands for the
// running mode (velocity, height, pitch, another registered gait) take effect without
// re-entering. Gaits that are part of the interface but not registered are refused with a
// reason, so the machine reports BAN_TRANS.
#pragma once

#include "modes/command_ranges.hpp"
#include "modes/locomotion_gait.hpp"
#include "modes/mode.hpp"

namespace cerebellum {

class LocomotionMode final : public Mode {
 public:
  explicit LocomotionMode(const GaitRegistry& gaits, const LocomotionLimits& limits = {},
                          const LocomotionStandRanges& ranges = {});
  ModeId id() const override { return ModeId::Locomotion; }
  const char* check(const HighLevelCommand& command) const override;
  void enter(const RobotState& state, const HighLevelCommand& command) override;
  void update(const RobotState& state, const HighLevelCommand& command) override;
  void exit() override;
  void run(const RobotState& state, JointCommand& command) override;
  ContactPlan contact_plan() const override;
  int gait_id() const override { return gait_id_; }
  int progress_percent() const override;
  bool damping_protection() const override { return running_ != nullptr && running_->damping_protection(); }

  // the command as the gait sees it: clamped to the interface's ranges
  LocomotionCommand clamped(const HighLevelCommand& command) const;

 private:
  const GaitRegistry& gaits_;
  LocomotionLimits limits_;
  LocomotionStandRanges ranges_;
  LocomotionGait* running_ = nullptr;
  int gait_id_ = 1;
};

// why a locomotion gait id is refused when no gait is registered for it (a static string)
const char* unavailable_gait_reason(int gait_id);

}  // namespace cerebellum
