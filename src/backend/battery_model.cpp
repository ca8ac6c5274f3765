#include "backend/battery_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace cerebellum {
namespace {

// a typical lithium-ion (NMC) discharge curve: open-circuit voltage every 10 % of charge
constexpr std::array<double, 11> kCellVoltageEvery10Percent{3.00, 3.30, 3.45, 3.55, 3.62, 3.68,
                                                            3.75, 3.84, 3.94, 4.06, 4.20};

}  // namespace

double cell_open_circuit_voltage_v(double state_of_charge_percent) {
  const double x = std::clamp(state_of_charge_percent, 0.0, 100.0) / 10.0;
  const auto i = std::min<std::size_t>(static_cast<std::size_t>(x), kCellVoltageEvery10Percent.size() - 2);
  const double t = x - static_cast<double>(i);
  return kCellVoltageEvery10Percent[i] + t * (kCellVoltageEvery10Percent[i + 1] - kCellVoltageEvery10Percent[i]);
}

double motor_electrical_power_w(double joint_torque_nm, double joint_speed_rad_s) {
  const double motor_current_a = joint_torque_nm / (robot::kGearRatio * robot::kMotorKt);
  const double copper_loss_w = motor_current_a * motor_current_a * robot::kMotorResistanceOhm;
  return std::max(0.0, joint_torque_nm * joint_speed_rad_s + copper_loss_w);
}

double pack_current_a(double power_w, double ocv_v, double r_ohm) {
  if (power_w <= 0.0) return 0.0;
  // r I^2 - ocv I + P = 0, the smaller root (the pack's working point)
  const double discriminant = ocv_v * ocv_v - 4.0 * r_ohm * power_w;
  if (discriminant <= 0.0) return ocv_v / (2.0 * r_ohm);
  return (ocv_v - std::sqrt(discriminant)) / (2.0 * r_ohm);
}

BatteryModel::BatteryModel(const BatteryParameters& parameters)
    : parameters_(parameters),
      state_of_charge_percent_(std::clamp(parameters.initial_state_of_charge_percent, 0.0, 100.0)),
      voltage_v_(parameters.cells * cell_open_circuit_voltage_v(state_of_charge_percent_)) {}

void BatteryModel::update(double motor_power_w, double dt_s) {
  const double ocv_v = parameters_.cells * cell_open_circuit_voltage_v(state_of_charge_percent_);
  current_a_ = pack_current_a(motor_power_w + parameters_.idle_power_w, ocv_v, parameters_.internal_resistance_ohm);
  voltage_v_ = ocv_v - current_a_ * parameters_.internal_resistance_ohm;
  const double drawn_ah = current_a_ * dt_s / 3600.0;
  state_of_charge_percent_ = std::max(0.0, state_of_charge_percent_ - 100.0 * drawn_ah / parameters_.capacity_ah);
}

BatteryReading BatteryModel::reading() const {
  BatteryReading reading;
  reading.present = true;
  reading.current_a = current_a_;
  reading.state_of_charge_percent = state_of_charge_percent_;
  reading.voltage_v = voltage_v_;
  return reading;
}

}  // namespace cerebellum
