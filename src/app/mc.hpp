// The MC assembled from its configuration: robot, estimator, modes, state machine, arbiter and
// loop. Client interfaces attach to it (arbiter sources, loop observers, substep participants).
#pragma once

#include "app/control_loop.hpp"
#include "app/mc_config.hpp"
#include "backend/mujoco_backend.hpp"
#include "estimation/body_state_estimator.hpp"
#include "modes/high_level_machine.hpp"
#include "modes/lifted_mode.hpp"
#include "modes/locomotion_mode.hpp"
#include "modes/locomotion_stand_gait.hpp"
#include "modes/walking_gaits.hpp"
#include "modes/passive_modes.hpp"
#include "modes/pose_control_mode.hpp"
#include "modes/qp_stand_mode.hpp"
#include "modes/recovery_stand_mode.hpp"
#include "modes/source_arbiter.hpp"

namespace cerebellum {

// the command the MC runs by itself at start
HighLevelCommand startup_command(Startup startup);

class Mc {
 public:
  // throws (std::runtime_error) when the robot model cannot be loaded
  explicit Mc(const McConfig& config);
  Mc(const Mc&) = delete;
  Mc& operator=(const Mc&) = delete;

  MujocoBackend& backend() { return backend_; }
  HighLevelMachine& machine() { return machine_; }
  SourceArbiter& arbiter() { return arbiter_; }
  ControlLoop& loop() { return loop_; }
  const McConfig& config() const { return config_; }
  const WalkingGaits& walking() const { return walking_; }

 private:
  McConfig config_;
  MujocoBackend backend_;
  BodyStateEstimator estimator_;
  OffMode off_;
  PureDamperMode pure_damper_;
  RecoveryStandMode recovery_stand_;
  QpStandMode qp_stand_;
  PoseControlMode pose_control_;
  LiftedMode lifted_;
  GaitRegistry gaits_;
  WalkingGaits walking_;
  LocomotionStandGait qp_stand_gait_;
  LocomotionMode locomotion_;
  HighLevelMachine machine_;
  SourceArbiter arbiter_;
  ControlLoop loop_;
};

}  // namespace cerebellum
