#include "safety/lift_detector.hpp"

#include <algorithm>

#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

constexpr double kGravity = robot::kGravityMPerS2;

// robot time since the previous call, 0 on the first; bounded so a pause cannot fake a lift
double step_s(const RobotState& state, LiftWatch& watch) {
  const double dt = watch.has_time ? std::clamp(state.time_s - watch.last_time_s, 0.0, 0.1) : 0.0;
  watch.last_time_s = state.time_s;
  watch.has_time = true;
  return dt;
}

}  // namespace

bool detect_lifted(const RobotState& state, LiftWatch& watch, const LiftDetectorConfig& config) {
  const double dt = step_s(state, watch);
  watch.loaded_s = 0.0;
  // vertical motion from the IMU, leaky so that bias cannot build up
  const double leak = dt / config.integration_leak_s;
  watch.rise_speed_m_s += dt * state.accel_world.z() - leak * watch.rise_speed_m_s;
  watch.rise_m += dt * watch.rise_speed_m_s - leak * watch.rise_m;

  bool any_load = false;
  for (double contact : state.contact) any_load |= contact > 0.5;
  const bool supported = state.accel_world.z() + kGravity > config.min_support_fraction * kGravity;
  watch.unloaded_s = !any_load && supported ? watch.unloaded_s + dt : 0.0;
  const bool rose = watch.rise_m > config.min_rise_m || watch.rise_speed_m_s > config.min_rise_speed_m_s;
  return watch.unloaded_s >= config.unloaded_time_s && rose;
}

bool detect_landed(const RobotState& state, LiftWatch& watch, const LiftDetectorConfig& config) {
  const double dt = step_s(state, watch);
  int loaded = 0;
  for (double contact : state.contact) loaded += contact > 0.5 ? 1 : 0;
  watch.loaded_s = loaded >= config.landed_feet ? watch.loaded_s + dt : 0.0;
  return watch.loaded_s >= config.landed_time_s;
}

}  // namespace cerebellum
