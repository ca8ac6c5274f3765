// The battery pack and the motors' electrical power, checked against first principles.
#include "backend/battery_model.hpp"

#include <gtest/gtest.h>

#include "backend/motor_model.hpp"

namespace cerebellum {
namespace {

TEST(BatteryModel, ACellReadsEmptyNominalAndFullVoltages) {
  EXPECT_DOUBLE_EQ(cell_open_circuit_voltage_v(0.0), 3.0);
  EXPECT_DOUBLE_EQ(cell_open_circuit_voltage_v(100.0), 4.2);
  EXPECT_DOUBLE_EQ(cell_open_circuit_voltage_v(150.0), 4.2);  // clamped
  // the pack's 21.6 V nominal (3.6 V a cell) lies in the flat middle of the curve
  EXPECT_GT(cell_open_circuit_voltage_v(50.0), 3.6);
  EXPECT_LT(cell_open_circuit_voltage_v(30.0), 3.6);
  for (double soc = 0.0; soc < 100.0; soc += 0.5) {
    EXPECT_LT(cell_open_circuit_voltage_v(soc), cell_open_circuit_voltage_v(soc + 0.5)) << soc;
  }
}

TEST(BatteryModel, ThePacksCurrentDeliversThePowerAtItsTerminalVoltage) {
  const double ocv = 24.0, r = 0.12;
  for (double power : {1.0, 25.0, 300.0, 1000.0}) {
    const double current = pack_current_a(power, ocv, r);
    EXPECT_NEAR((ocv - current * r) * current, power, 1e-9 * power) << power;
  }
  EXPECT_EQ(pack_current_a(0.0, ocv, r), 0.0);
  // beyond the pack's maximum power ocv^2 / 4 r = 1200 W: the current of the maximum
  EXPECT_DOUBLE_EQ(pack_current_a(5000.0, ocv, r), ocv / (2 * r));
}

TEST(BatteryModel, TheStateOfChargeFallsByTheChargeDrawn) {
  BatteryParameters parameters;
  parameters.idle_power_w = 50.0;
  BatteryModel battery(parameters);
  double drawn_ah = 0.0;
  const double dt = 0.001;
  for (int step = 0; step < 60000; ++step) {  // one minute
    battery.update(100.0, dt);
    const BatteryReading reading = battery.reading();
    // the 150 W load at the terminal voltage
    EXPECT_NEAR(reading.voltage_v * reading.current_a, 150.0, 1e-6);
    drawn_ah += reading.current_a * dt / 3600.0;
  }
  const BatteryReading reading = battery.reading();
  EXPECT_TRUE(reading.present);
  EXPECT_NEAR(reading.state_of_charge_percent, 100.0 - 100.0 * drawn_ah / 4.5, 1e-9);
  // about 6 A from a full pack (25.2 V) for a minute: 0.1 Ah, 2.2 % of 4.5 Ah
  EXPECT_NEAR(100.0 - reading.state_of_charge_percent, 2.2, 0.1);
}

TEST(BatteryModel, AMotorDrawsItsMechanicalPowerPlusCopperLossButNeverReturnsPower) {
  // 3.875 N m at the joint is 10 A in the motor (gear 7.75, KT 0.05): 17.3 W copper loss
  EXPECT_NEAR(motor_electrical_power_w(3.875, 0.0), 17.3, 1e-9);
  EXPECT_NEAR(motor_electrical_power_w(3.875, 2.0), 7.75 + 17.3, 1e-9);
  EXPECT_EQ(motor_electrical_power_w(3.875, -10.0), 0.0);  // braking
}

TEST(MotorDriverFaults, TheDriverWarnsAt82StopsAt87AndWatchesTheBusVoltage) {
  EXPECT_EQ(motor_driver_faults(81.9, 24.0), kMotorOk);
  EXPECT_EQ(motor_driver_faults(82.0, 24.0), kMotorTemperatureWarning);
  EXPECT_EQ(motor_driver_faults(87.0, 24.0), kMotorTemperatureWarning | kMotorOverTemperature);
  EXPECT_EQ(motor_driver_faults(30.0, 17.9), kMotorUnderVoltage);
  EXPECT_EQ(motor_driver_faults(30.0, 26.1), kMotorOverVoltage);
}

TEST(MotorDriverFaults, ATrippedVoltageLimitClearsOnlyHalfAVoltInside) {
  EXPECT_EQ(motor_driver_faults(30.0, 18.2, kMotorUnderVoltage), kMotorUnderVoltage);
  EXPECT_EQ(motor_driver_faults(30.0, 18.6, kMotorUnderVoltage), kMotorOk);
  EXPECT_EQ(motor_driver_faults(30.0, 18.2, kMotorOk), kMotorOk);
  EXPECT_EQ(motor_driver_faults(30.0, 25.8, kMotorOverVoltage), kMotorOverVoltage);
  EXPECT_EQ(motor_driver_faults(30.0, 25.4, kMotorOverVoltage), kMotorOk);
}

}  // namespace
}  // namespace cerebellum
