#include "backend/motor_model.hpp"

#include <algorithm>
#include <cmath>

namespace cerebellum {

double motor_law_torque(double q_des, double qd_des, double kp, double kd, double tau_ff, double q, double qd) {
  return tau_ff + kp * (q_des - q) + kd * (qd_des - qd);
}

double limit_motor_torque(double tau_nm, double qd_rad_s, const MotorLimits& limits) {
  double available = limits.torque_max_nm;
  const double speed = std::abs(qd_rad_s);
  if (tau_nm * qd_rad_s > 0.0 && speed > limits.full_torque_speed_rad_s) {
    const double fraction =
        (limits.no_load_speed_rad_s - speed) / (limits.no_load_speed_rad_s - limits.full_torque_speed_rad_s);
    available *= std::clamp(fraction, 0.0, 1.0);
  }
  return std::clamp(tau_nm, -available, available);
}

std::uint32_t motor_driver_faults(double temperature_c, double bus_voltage_v, std::uint32_t previous) {
  std::uint32_t faults = kMotorOk;
  if (temperature_c >= robot::kMotorWarningTemperatureC) faults |= kMotorTemperatureWarning;
  if (temperature_c >= robot::kMotorShutdownTemperatureC) faults |= kMotorOverTemperature;
  const double hysteresis_v = robot::kDriverVoltageHysteresisV;
  const double under_v = robot::kDriverUnderVoltageV + ((previous & kMotorUnderVoltage) ? hysteresis_v : 0.0);
  const double over_v = robot::kDriverOverVoltageV - ((previous & kMotorOverVoltage) ? hysteresis_v : 0.0);
  if (bus_voltage_v < under_v) faults |= kMotorUnderVoltage;
  if (bus_voltage_v > over_v) faults |= kMotorOverVoltage;
  return faults;
}

std::uint32_t motor_over_speed(double joint_velocity_rad_s) {
  return std::abs(joint_velocity_rad_s) > robot::kNoLoadSpeedRadS ? kMotorOverSpeed : kMotorOk;
}

MotorThermalModel::MotorThermalModel(const MotorThermalParameters& parameters)
    : parameters_(parameters), winding_(parameters.winding) {}

void MotorThermalModel::update(double joint_torque_nm, double dt_s) {
  const double current_a = joint_torque_nm / (parameters_.gear_ratio * parameters_.torque_constant_nm_per_a);
  const double heating_w = current_a * current_a * parameters_.winding_resistance_ohm;
  winding_.update(heating_w, dt_s);
}

}  // namespace cerebellum
