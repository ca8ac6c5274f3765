// The robot's battery pack: open-circuit voltage from the state of charge, terminal voltage that
// sags under the load's current through the internal resistance, and a state of charge that
// falls with the charge drawn. The load is the motors' electrical power plus the idle boards.
#pragma once

#include "core/motor_health.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {

struct BatteryParameters {
  int cells = robot::kBatteryCells;
  double capacity_ah = robot::kBatteryCapacityAh;
  double internal_resistance_ohm = robot::kBatteryInternalResistanceOhm;
  double idle_power_w = robot::kIdleElectricalPowerW;
  double initial_state_of_charge_percent = 100.0;
};

// open-circuit voltage of one lithium-ion cell (3.0 V empty, 3.6 V nominal, 4.2 V full);
// state of charge clamped to 0..100 %
double cell_open_circuit_voltage_v(double state_of_charge_percent);

// electrical power one motor draws from the bus: mechanical power (joint torque times speed) plus
// the coil's copper loss; braking power is burnt in the driver, not returned (never below 0)
double motor_electrical_power_w(double joint_torque_nm, double joint_speed_rad_s);

// the current a pack of open-circuit voltage ocv_v and resistance r_ohm delivers to a load of
// power_w (V = ocv - I r, P = V I); a load beyond the pack's maximum (ocv^2 / 4 r) gets the
// current of that maximum
double pack_current_a(double power_w, double ocv_v, double r_ohm);

class BatteryModel {
 public:
  explicit BatteryModel(const BatteryParameters& parameters = {});
  // the motors draw motor_power_w (the idle load is added) for dt_s
  void update(double motor_power_w, double dt_s);
  BatteryReading reading() const;

 private:
  BatteryParameters parameters_;
  double state_of_charge_percent_;
  double voltage_v_;  // at the working point of the last update (open circuit before any)
  double current_a_ = 0.0;
};

}  // namespace cerebellum
