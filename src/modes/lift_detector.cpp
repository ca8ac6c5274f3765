#include "modes/lift_detector.hpp"

#include <algorithm>

namespace cerebellum {
namespace {

constexpr double kGravity = 9.81;

}  // namespace

LiftDetector::LiftDetector(const LiftDetectorConfig& config) : config_(config) {}

void LiftDetector::reset() {
  has_time_ = false;
  unloaded_s_ = rise_speed_m_s_ = rise_m_ = loaded_s_ = 0.0;
}

double LiftDetector::step_s(const RobotState& state) {
  const double dt = has_time_ ? std::clamp(state.time_s - last_time_s_, 0.0, 0.1) : 0.0;
  last_time_s_ = state.time_s;
  has_time_ = true;
  return dt;
}

bool LiftDetector::lifted(const RobotState& state) {
  const double dt = step_s(state);
  loaded_s_ = 0.0;
  // vertical motion from the IMU, leaky so that bias cannot build up
  const double leak = dt / config_.integration_leak_s;
  rise_speed_m_s_ += dt * state.accel_world.z() - leak * rise_speed_m_s_;
  rise_m_ += dt * rise_speed_m_s_ - leak * rise_m_;

  bool any_load = false;
  for (double contact : state.contact) any_load |= contact > 0.5;
  const bool supported = state.accel_world.z() + kGravity > config_.min_support_fraction * kGravity;
  unloaded_s_ = !any_load && supported ? unloaded_s_ + dt : 0.0;
  const bool rose = rise_m_ > config_.min_rise_m || rise_speed_m_s_ > config_.min_rise_speed_m_s;
  return unloaded_s_ >= config_.unloaded_time_s && rose;
}

bool LiftDetector::landed(const RobotState& state) {
  const double dt = step_s(state);
  int loaded = 0;
  for (double contact : state.contact) loaded += contact > 0.5 ? 1 : 0;
  loaded_s_ = loaded >= config_.landed_feet ? loaded_s_ + dt : 0.0;
  return loaded_s_ >= config_.landed_time_s;
}

HighLevelCommand command_after_landing(const HighLevelCommand& lifted_from) {
  HighLevelCommand command = lifted_from;
  command.duration = 0;
  command.vel_des = {};
  command.contact = 0x0F;
  if (lifted_from.mode == static_cast<int>(ModeId::Locomotion)) {
    command.gait_id = lifted_from.gait_id <= 30 ? 1 : 31;
  } else if (lifted_from.mode == static_cast<int>(ModeId::QpStand)) {
    command.gait_id = 1;
  } else {
    command = HighLevelCommand{};
    command.mode = static_cast<int>(ModeId::QpStand);
    command.gait_id = 1;
  }
  return command;
}

}  // namespace cerebellum
