#include "safety/jump_gate.hpp"

#include <algorithm>
#include <cmath>

namespace cerebellum {

const char* jump_refusal(const RobotState& state, const JumpGateLimits& limits) {
  if (!state.valid) return "jump refused: the state estimate cannot be trusted";
  for (const std::uint32_t faults : state.motor_faults) {
    if (faults != 0) return "jump refused: a motor reports a fault or warning";
  }
  if (state.velocity_world.head<2>().norm() > limits.max_speed_m_s) {
    return "jump refused: moving faster than 0.3 m/s (stop first)";
  }
  if (std::abs(state.omega_world.z()) > limits.max_yaw_rate_rad_s) return "jump refused: turning (stop first)";
  if (std::max(std::abs(state.rpy.x()), std::abs(state.rpy.y())) > limits.max_tilt_rad) {
    return "jump refused: the trunk is tilted";
  }
  if (std::atan(state.ground.gradient.norm()) > limits.max_slope_rad) return "jump refused: on a slope";
  if (state.height_m < limits.min_height_m) return "jump refused: not standing";
  int feet_down = 0;
  for (const double contact : state.contact) feet_down += contact > 0.5 ? 1 : 0;
  if (feet_down < limits.min_feet_down) return "jump refused: not standing on four feet";
  return nullptr;
}

FlipGate flip_gate(const RobotState& state, Flip flip, const FlipGateLimits& limits) {
  for (const double temperature : state.temperature_c) {
    if (!(temperature <= limits.max_motor_temperature_c)) return FlipGate::OverHeat;
  }
  const double needed =
      flip == Flip::Front ? limits.front_flip_min_battery_percent : limits.back_flip_min_battery_percent;
  if (state.battery.present && !(state.battery.state_of_charge_percent >= needed)) return FlipGate::LowBattery;
  return FlipGate::Allowed;
}

}  // namespace cerebellum
