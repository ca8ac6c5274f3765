// Locomotion's stand gaits on the QP stand: gait 1 (with push recovery: after a push the body
// is pulled back over its feet) and gait 31 (without: a push is only damped). Height and pitch
// follow the command; velocity is ignored (a stand does not step).
#pragma once

#include "control/locomotion/gait_table.hpp"
#include "control/qp_stand.hpp"
#include "modes/locomotion_gait.hpp"

namespace cerebellum {

struct LocomotionStandConfig {
  QpStandConfig stand;
  PoseSpeed speed{0.8, 0.15, 0.3};
};

class LocomotionStandGait final : public LocomotionGait {
 public:
  static constexpr int kWithPushRecovery = kStandGaitId;
  static constexpr int kWithoutPushRecovery = kStandWithoutPushRecoveryGaitId;

  explicit LocomotionStandGait(const LocomotionStandConfig& config = {});
  void start(const RobotState& state, const LocomotionCommand& command) override;
  void update(const LocomotionCommand& command) override;
  void run(const RobotState& state, JointCommand& command) override;
  int progress_percent() const override;

  const QpStand& stand() const { return stand_; }

 private:
  LocomotionStandConfig config_;
  QpStand stand_;
};

}  // namespace cerebellum
