// The high-level modes and mode 11's gaits, built and registered with a state machine in one
// place: the MC and the tests run the same set.
#pragma once

#include <memory>
#include <string>

#include "core/robot_model.hpp"
#include "control/stand_up_controller.hpp"
#include "modes/high_level_machine.hpp"
#include "modes/jump_mode.hpp"
#include "modes/lifted_mode.hpp"
#include "modes/locomotion_stand.hpp"
#include "modes/locomotion_mode.hpp"
#include "modes/locomotion_stand_gait.hpp"
#include "modes/motion.hpp"
#include "modes/motion_mode.hpp"
#include "modes/passive_modes.hpp"
#include "modes/passive_trot_gait.hpp"
#include "modes/pose_control_mode.hpp"
#include "modes/push_recovery_stand_gait.hpp"
#include "modes/qp_stand_mode.hpp"
#include "modes/recovery_stand_mode.hpp"
#include "modes/two_leg_stand_mode.hpp"
#include "modes/user_gait.hpp"
#include "modes/user_gait_runner.hpp"
#include "modes/walking_gaits.hpp"

namespace cerebellum {

struct ModeSetConfig {
  double loop_period_s = 0.002;
  double damping_kd = robot::kDampingKd;  // PureDamper's joint damping, and the walking gaits' when the MPC fails
  StandUpConfig stand_up = default_stand_up_config();
  LocomotionStand locomotion_stand = LocomotionStand::Mpc;
  // mode 62's named motions (motions/ reads them from files); every step is checked by the mode
  // it runs in when the set is built
  MotionLibrary motions;
  // the robot's MuJoCo model, on which mode 64's balance is designed; empty: mode 64 is not offered
  std::string robot_model_path;
  // the flips' plans (control/jump/flip_trajectory), read when the set is built; empty: that flip
  // (16/20 back, 16/21 front) is refused
  std::string back_flip_path;
  std::string front_flip_path;
  // mode 11's velocity and swing-height clamps: the product's unless configured beyond it
  LocomotionLimits locomotion_limits;
  // the walking controller's settings (its tick is set from loop_period_s)
  LocomotionConfig locomotion;
};

class ModeSet {
 public:
  // throws std::invalid_argument naming the motion file and step that its mode refuses
  explicit ModeSet(const ModeSetConfig& config);
  ModeSet(const ModeSet&) = delete;
  ModeSet& operator=(const ModeSet&) = delete;

  // registers every mode with the machine (which keeps pointers: this set must outlive it)
  void add_to(HighLevelMachine& machine);

  const RecoveryStandMode& recovery_stand() const { return recovery_stand_; }
  const WalkingGaits& walking() const { return walking_; }
  const LocomotionStandGait& qp_stand_gait() const { return qp_stand_gait_; }
  const PassiveTrotGait& passive_trot() const { return passive_trot_; }
  const PushRecoveryStandGait& push_recovery_stand() const { return push_recovery_stand_; }
  const MotionMode& motion() const { return motion_; }
  const UserGaitRunner& user_gait() const { return user_gait_; }
  const JumpMode& jump() const { return jump_; }
  // where the high-level interface hands over a newly uploaded user gait (any thread)
  UserGaitSlot& user_gait_slot() { return user_gait_slot_; }
  // mode 11's gaits by id
  const GaitRegistry& gaits() const { return gaits_; }

 private:
  OffMode off_;
  PureDamperMode pure_damper_;
  RecoveryStandMode recovery_stand_;
  QpStandMode qp_stand_;
  PoseControlMode pose_control_;
  LiftedMode lifted_;
  GaitRegistry gaits_;
  WalkingGaits walking_;
  PassiveTrotGait passive_trot_;
  PushRecoveryStandGait push_recovery_stand_;
  UserGaitSlot user_gait_slot_;
  UserGaitRunner user_gait_;
  LocomotionStandGait qp_stand_gait_;
  LocomotionMode locomotion_;
  MotionLibrary motions_;
  MotionMode motion_;
  JumpMode jump_;
  JumpMode force_jump_;
  std::unique_ptr<TwoLegStandMode> two_leg_stand_;
};

}  // namespace cerebellum
