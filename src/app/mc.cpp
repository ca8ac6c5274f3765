#include "app/mc.hpp"

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

}  // namespace

Mc::Mc(const McConfig& config)
    : config_(config),
      backend_(config.robot),
      pure_damper_(pure_damper_config(config)),
      recovery_stand_(config.stand_up),
      machine_(config.loop_period_s, startup_command(config.startup)),
      arbiter_(machine_),
      loop_(backend_, estimator_, arbiter_, config.safety, config.loop_period_s) {
  machine_.add_mode(off_);
  machine_.add_mode(pure_damper_);
  machine_.add_mode(recovery_stand_);
}

}  // namespace cerebellum
