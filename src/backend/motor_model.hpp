// What a CyberDog2 joint motor and its driver do with a command: PD + feed-forward law,
// torque limit, speed-torque curve, and a first-order winding temperature model.
#pragma once

#include <cstdint>

#include "core/motor_health.hpp"
#include "backend/thermal_mass.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {

struct MotorLimits {
  double torque_max_nm = robot::kTorqueMaxNm;
  double full_torque_speed_rad_s = robot::kFullTorqueSpeedRadS;  // full torque below this joint speed
  double no_load_speed_rad_s = robot::kNoLoadSpeedRadS;          // driving torque reaches zero here
};

// tau = tau_ff + kp (q_des - q) + kd (qd_des - qd)
double motor_law_torque(double q_des, double qd_des, double kp, double kd, double tau_ff, double q, double qd);

// The driver clamps to +-torque_max. While the torque drives the joint in its direction of
// motion (tau * qd > 0) the available torque falls linearly from full at full_torque_speed to
// zero at no_load_speed; braking torque (tau * qd <= 0) is limited by torque_max only.
double limit_motor_torque(double tau_nm, double qd_rad_s, const MotorLimits& limits);

struct MotorThermalParameters {
  ThermalMassParameters winding{robot::kAmbientTemperatureC, 1.2, 60.0};  // winding to ambient
  double gear_ratio = robot::kGearRatio;
  double torque_constant_nm_per_a = robot::kMotorKt;  // motor side
  double winding_resistance_ohm = robot::kMotorResistanceOhm;
};

// what a driver reports of its own condition: the coil's warning (82 deg C) and shutdown
// (87 deg C) temperatures, a bus voltage outside the driver's range (MotorFault bits); a driver
// reporting an error stops driving its motor. A voltage limit that tripped (previous) clears only
// once the voltage is back inside by the hysteresis: a sagging pack whose voltage recovers as soon
// as the motors stop does not switch them on and off every step
std::uint32_t motor_driver_faults(double temperature_c, double bus_voltage_v, std::uint32_t previous = kMotorOk);
// kMotorOverSpeed when the joint turns faster than the motor's no-load speed (it is driven from
// outside: a fall, an impact), else kMotorOk
std::uint32_t motor_over_speed(double joint_velocity_rad_s);

// copper loss heats the winding, conduction to ambient cools it
class MotorThermalModel {
 public:
  explicit MotorThermalModel(const MotorThermalParameters& parameters);
  void update(double joint_torque_nm, double dt_s);
  double temperature_c() const { return winding_.temperature_c(); }

 private:
  MotorThermalParameters parameters_;
  ThermalMass winding_;
};

}  // namespace cerebellum
