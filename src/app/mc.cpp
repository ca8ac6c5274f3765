#include "app/mc.hpp"

#include "control/qp/goldfarb_idnani_solver.hpp"

#include <cmath>

namespace cerebellum {

HighLevelCommand startup_command(Startup startup) {
  HighLevelCommand command;
  command.mode = static_cast<int>(startup == Startup::Stand   ? ModeId::RecoveryStand
                                  : startup == Startup::Off ? ModeId::Off
                                                            : ModeId::PureDamper);
  return command;
}

namespace {

PureDamperConfig pure_damper_config(const McConfig& config) {
  PureDamperConfig damper = default_pure_damper_config();
  damper.damping_kd = config.safety.damping_kd;
  return damper;
}

WalkingGaitsConfig walking_config(const McConfig& config) {
  WalkingGaitsConfig walking;
  walking.locomotion.tick_s = config.loop_period_s;
  walking.locomotion.ticks_per_segment = static_cast<int>(std::lround(0.03 / config.loop_period_s));
  walking.failure_damping_kd = config.safety.damping_kd;
  return walking;
}

}  // namespace

Mc::Mc(const McConfig& config)
    : config_(config),
      backend_(config.robot),
      pure_damper_(pure_damper_config(config)),
      recovery_stand_(config.stand_up),
      lifted_(default_lifted_config()),
      walking_(walking_config(config), std::make_unique<qp::GoldfarbIdnaniSolver>()),
      locomotion_(gaits_),
      machine_(config.loop_period_s, startup_command(config.startup)),
      arbiter_(machine_),
      loop_(backend_, estimator_, arbiter_, config.safety, config.loop_period_s) {
  machine_.add_mode(off_);
  machine_.add_mode(pure_damper_);
  machine_.add_mode(recovery_stand_);
  machine_.add_mode(qp_stand_);
  machine_.add_mode(pose_control_);
  machine_.add_mode(lifted_);
  // the walking gaits run on the MPC locomotion controller; the stands on the configured one
  for (int gait : {2, 3, 4, 7, 10, 26, 27}) gaits_.add(gait, walking_);
  LocomotionGait& stand = config.locomotion_stand == LocomotionStand::Mpc ? static_cast<LocomotionGait&>(walking_)
                                                                          : qp_stand_gait_;
  gaits_.add(1, stand);
  gaits_.add(31, stand);
  machine_.add_mode(locomotion_);
}

}  // namespace cerebellum
