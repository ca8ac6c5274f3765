#include "loop/mc.hpp"

#include <stdexcept>

#include "motions/motion_gaits.hpp"

namespace cerebellum {

HighLevelCommand startup_command(Startup startup) {
  HighLevelCommand command;
  command.mode = static_cast<int>(startup == Startup::Stand ? ModeId::RecoveryStand
                                  : startup == Startup::Off ? ModeId::Off
                                                            : ModeId::PureDamper);
  return command;
}

namespace {

ModeSetConfig mode_set_config(const McConfig& config) {
  ModeSetConfig modes;
  modes.loop_period_s = config.loop_period_s;
  modes.damping_kd = config.safety.damping_kd;
  modes.stand_up = config.stand_up;
  modes.locomotion_stand = config.locomotion_stand;
  modes.robot_model_path = config.robot.model_path;
  modes.back_flip_path = config.back_flip_path;
  modes.front_flip_path = config.front_flip_path;
  modes.locomotion_limits = config.locomotion_limits;
  modes.locomotion = config.locomotion;
  modes.motions = load_motion_library(config.motions);
  attach_user_gaits(modes.motions);
  return modes;
}

RobotBackend& require_backend(const std::unique_ptr<RobotBackend>& backend) {
  if (!backend) throw std::invalid_argument("Mc: no robot backend");
  return *backend;
}

}  // namespace

Mc::Mc(const McConfig& config, McRobot robot)
    : config_(config),
      backend_(std::move(robot.backend)),
      simulation_(robot.simulation),
      faults_(robot.faults),
      modes_(mode_set_config(config)),
      user_gait_upload_(modes_.user_gait_slot()),
      machine_(config.loop_period_s, startup_command(config.startup)),
      aliengo_(config.aliengo_session),
      arbiter_(machine_),
      loop_(require_backend(backend_), estimator_, arbiter_, config.safety, config.loop_period_s) {
  modes_.add_to(machine_);
  machine_.add_source_stage(aliengo_);
}

Simulation& Mc::simulation() {
  if (simulation_ == nullptr) throw std::logic_error("Mc: the robot is not simulated (no simulation handle)");
  return *simulation_;
}

}  // namespace cerebellum
