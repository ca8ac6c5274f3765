// The MPC gaits of mode 11 (the stepping gaits of the gait table, and its stands when served by
// the MPC): one LocomotionGait registered under every such gait id, so a gait or velocity change
// while walking updates the running controller. It plans the contacts (the gait's schedule) for
// the estimator and falls back to joint damping when the MPC keeps failing.
#pragma once

#include <memory>

#include "core/robot_model.hpp"
#include "control/locomotion/locomotion_controller.hpp"
#include "modes/locomotion_gait.hpp"

namespace cerebellum {

struct WalkingGaitsConfig {
  LocomotionConfig locomotion;
  double failure_damping_kd = robot::kDampingKd;
};

// the locomotion controller's target for a (clamped) mode-11 command; a step height below 1 cm
// (0 = not given) means the gait's default step height (gait table)
LocomotionTarget locomotion_target_from(const LocomotionCommand& command);

class WalkingGaits final : public LocomotionGait {
 public:
  WalkingGaits(const WalkingGaitsConfig& config, std::unique_ptr<qp::QpSolver> solver);

  const char* check(const HighLevelCommand& command) const override;
  void start(const RobotState& state, const LocomotionCommand& command) override;
  void update(const LocomotionCommand& command) override;
  void run(const RobotState& state, JointCommand& command) override;
  void stop() override;
  // the new gait's command for the running controller: it changes pattern where it can
  void take_over(const RobotState& /*state*/, const LocomotionCommand& command) override { update(command); }
  ContactPlan contact_plan() const override { return plan_; }
  int progress_percent() const override { return 100; }

  // the MPC failed several times in a row: the robot is being damped down
  bool failed() const { return !controller_.healthy(); }
  bool damping_protection() const override { return failed(); }
  const LocomotionController& controller() const { return controller_; }
  void anchor_position_at_trunk(const RobotState& state) { controller_.anchor_position_at_trunk(state); }
  // a user gait drives the controller directly: its schedule once, then its own targets
  void play(std::shared_ptr<const ContactSequence> sequence, const RobotState& state) {
    controller_.play(std::move(sequence), state);
  }
  void steer(const LocomotionTarget& target) { controller_.set_command(target); }

 private:
  WalkingGaitsConfig config_;
  LocomotionController controller_;
  // the schedule of the last healthy run; kept while the MPC has failed, none once stopped
  ContactPlan plan_;
};

}  // namespace cerebellum
