#include "modes/safety_reaction.hpp"

#include "modes/watched_modes.hpp"
#include "safety/body_watch.hpp"

namespace cerebellum {
namespace {

HighLevelCommand command_of(ModeId mode) {
  HighLevelCommand command;
  command.mode = static_cast<int>(mode);
  return command;
}

}  // namespace

std::optional<ModeId> SafetyReaction::health_target(ModeId current) const {
  if (!health_.protecting()) return std::nullopt;
  const ModeId target = health_.protection == Protection::Stopped ? ModeId::Off : ModeId::PureDamper;
  // damping does not wake motors that are already off
  if (current == target || (target == ModeId::PureDamper && current == ModeId::Off)) return std::nullopt;
  return target;
}

const char* SafetyReaction::refusal(ModeId target, ModeId current) const {
  if (health_.protecting()) {
    if (health_.causes & (kHealthMotorError | kHealthMotorWarning)) {
      return "motor error or warning: commands are ignored until it clears";
    }
    if (health_.causes & (kHealthBatteryCritical | kHealthBatteryReading)) {
      return "battery critically low: commands are ignored until it is charged";
    }
    return "sensor fault (IMU or state estimate): commands are ignored until it clears";
  }
  const bool protected_stop = orientation_error_ || foot_position_error_ != 0;
  if (protected_stop && target != ModeId::RecoveryStand && target != ModeId::Off && target != ModeId::PureDamper) {
    return orientation_error_ ? "orientation error: only a recovery stand clears it"
                              : "foot position error: only a recovery stand clears it";
  }
  if (current == ModeId::Lifted && (target == ModeId::QpStand || target == ModeId::Locomotion)) {
    return "lifted: the stand resumes by itself once the robot is set down";
  }
  return nullptr;
}

BodyReaction SafetyReaction::watch_body(const RobotState& state, const ModeSwitcher& switcher) {
  const Mode& current = switcher.current();
  const ModeId id = current.id();
  if (id == ModeId::Lifted) {
    if (detect_landed(state, lift_watch_, lift_config_) && switcher.find(resume_command_.mode) != nullptr) {
      return {BodyReaction::Action::Land, resume_command_};
    }
    return {};
  }
  if (!watches_body(id)) return {};
  if (current.turns_over()) {
    lift_watch_ = LiftWatch{};
    return {};
  }
  const SafetyReport report = check_body(state, watches_feet(id));
  if (report.body_fault() && switcher.find(ModeId::PureDamper) != nullptr) {
    // tipped over or a foot out of reach: damp the joints, wait for a recovery stand
    orientation_error_ = report.orientation_error;
    foot_position_error_ = report.footpos_error;
    return {BodyReaction::Action::Damp, command_of(ModeId::PureDamper)};
  }
  if (switcher.find(ModeId::Lifted) == nullptr) return {};
  // a jump leaves the ground on purpose: its watch starts afresh once it stands again
  if (current.airborne()) {
    lift_watch_ = LiftWatch{};
    return {};
  }
  if (!detect_lifted(state, lift_watch_, lift_config_)) return {};
  resume_command_ = command_after_landing(switcher.running_command());
  return {BodyReaction::Action::Lift, command_of(ModeId::Lifted)};
}

void SafetyReaction::on_switch(ModeId entered) {
  lift_watch_ = LiftWatch{};
  if (entered == ModeId::RecoveryStand) {
    orientation_error_ = false;
    foot_position_error_ = 0;
  }
}

std::optional<SwitchStatus> SafetyReaction::health_status() const {
  if (health_.protection == Protection::Stopped) return SwitchStatus::EmergencyStop;
  if (health_.protecting()) return SwitchStatus::HighDamping;
  return std::nullopt;
}

std::optional<SwitchStatus> SafetyReaction::protection_status() const {
  if (const std::optional<SwitchStatus> health = health_status()) return health;
  // the seed (000, robot_control_response, ori_error and footpos_error): both trigger "the high
  // damping protection mode", EDAMP; the reference's "emergency stop" for ori_error loses to it
  if (orientation_error_ || foot_position_error_ != 0) return SwitchStatus::HighDamping;
  return std::nullopt;
}

}  // namespace cerebellum
