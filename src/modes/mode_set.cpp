#include "modes/mode_set.hpp"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "control/locomotion/gait_table.hpp"
#include "control/qp/goldfarb_idnani_solver.hpp"
#include "control/jump/flip_trajectory.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

PureDamperConfig pure_damper_config(const ModeSetConfig& config) {
  PureDamperConfig damper = default_pure_damper_config();
  damper.damping_kd = config.damping_kd;
  return damper;
}

WalkingGaitsConfig walking_config(const ModeSetConfig& config) {
  WalkingGaitsConfig walking;
  walking.locomotion = config.locomotion;
  walking.locomotion.tick_s = config.loop_period_s;
  walking.locomotion.ticks_per_segment = static_cast<int>(std::lround(kGaitSegmentS / config.loop_period_s));
  walking.failure_damping_kd = config.damping_kd;
  return walking;
}

// a flip's file, read once with its reader's precise reason (throws std::invalid_argument)
std::optional<FlipTrajectory> flip_file(const std::string& path, const char* name) {
  if (path.empty()) return std::nullopt;
  std::string error;
  std::optional<FlipTrajectory> trajectory = read_flip_trajectory(path, robot::kTorqueMaxNm, error);
  if (!trajectory) throw std::invalid_argument(std::string(name) + ": " + error);
  return trajectory;
}

FlipPlans flip_plans(const ModeSetConfig& config) {
  return {flip_file(config.back_flip_path, "back flip"), flip_file(config.front_flip_path, "front flip")};
}

JumpControllerConfig jump_config(const ModeSetConfig& config) {
  JumpControllerConfig jump = default_jump_controller_config();
  jump.damping_kd = config.damping_kd;
  return jump;
}

TwoLegStandConfig two_leg_stand_config(const ModeSetConfig& config) {
  TwoLegStandConfig two_leg;
  two_leg.model_path = config.robot_model_path;
  two_leg.control_period_s = config.loop_period_s;
  two_leg.damping_kd = config.damping_kd;
  return two_leg;
}

}  // namespace

ModeSet::ModeSet(const ModeSetConfig& config)
    : pure_damper_(pure_damper_config(config)),
      recovery_stand_(config.stand_up),
      lifted_(default_lifted_config()),
      walking_(walking_config(config), std::make_unique<qp::GoldfarbIdnaniSolver>()),
      passive_trot_(walking_, PassiveFollowConfig{}, config.loop_period_s),
      push_recovery_stand_(walking_, PushRecoveryStandConfig{}, config.loop_period_s),
      user_gait_(walking_, user_gait_slot_),
      locomotion_(gaits_, config.locomotion_limits),
      motions_(config.motions),
      motion_(motions_, {&pose_control_, &qp_stand_, &locomotion_, &recovery_stand_}, user_gait_slot_, user_gait_),
      jump_(ModeId::Jump3d, jump_config(config), flip_plans(config)),
      force_jump_(ModeId::ForceJump, jump_config(config)) {
  if (!config.robot_model_path.empty()) {
    two_leg_stand_ = std::make_unique<TwoLegStandMode>(two_leg_stand_config(config));
  }
  // the stepping gaits of the table run on the MPC locomotion controller; the stands on the
  // configured one
  LocomotionGait& stand =
      config.locomotion_stand == LocomotionStand::Mpc ? static_cast<LocomotionGait&>(walking_) : qp_stand_gait_;
  for (const GaitSpec& gait : kGaitTable) gaits_.add(gait.id, gait_steps(gait) ? walking_ : stand);
  // on the walking controller, gait 1 steps to recover from a push (31 stays planted)
  if (config.locomotion_stand == LocomotionStand::Mpc) gaits_.add(kStandGaitId, push_recovery_stand_);
  // the passive trot drives the same controller, following pulls on the trunk
  gaits_.add(kPassiveTrotGaitId, passive_trot_);
  // the uploaded gait runs on it too
  gaits_.add(kUserGaitId, user_gait_);
  for (const Motion& motion : motions_.motions()) {
    for (std::size_t i = 0; i < motion.steps.size(); ++i) {
      if (const char* reason = motion_.check_step(motion, motion.steps[i])) {
        throw std::invalid_argument(motion.origin + ": motion " + std::to_string(motion.id) + ", step " +
                                    std::to_string(i + 1) + ": " + reason);
      }
    }
  }
}

void ModeSet::add_to(HighLevelMachine& machine) {
  machine.add_mode(off_);
  machine.add_mode(pure_damper_);
  machine.add_mode(recovery_stand_);
  machine.add_mode(qp_stand_);
  machine.add_mode(pose_control_);
  machine.add_mode(lifted_);
  machine.add_mode(locomotion_);
  machine.add_mode(motion_);
  machine.add_mode(jump_);
  machine.add_mode(force_jump_);
  // the two-leg stand's balance is designed on the robot's model: without one it is not offered
  if (two_leg_stand_) machine.add_mode(*two_leg_stand_);
}

}  // namespace cerebellum
