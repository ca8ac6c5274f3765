// What the robot's power and motor drivers report about themselves, in the MC's own terms; the
// interface adapters translate these bits into each wire format (motor_error, spi flags,
// joint_state_t.flags).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace cerebellum {

// per motor, one bit per condition its driver reports
enum MotorFault : std::uint32_t {
  kMotorOk = 0,
  kMotorDisconnected = 1u << 0,     // no answer from the driver
  kMotorOverTemperature = 1u << 1,  // coil at or above the shutdown temperature: the driver stops
  kMotorDriverFault = 1u << 2,      // driver chip
  kMotorUnderVoltage = 1u << 3,     // bus voltage below the driver's limit
  kMotorOverVoltage = 1u << 4,
  kMotorOverCurrent = 1u << 5,
  kMotorEncoderLost = 1u << 6,  // the position sensor does not answer or is not calibrated
  kMotorOverload = 1u << 7,
  kMotorTemperatureWarning = 1u << 8,  // coil at or above the warning temperature (not an error)
  kMotorOverSpeed = 1u << 9,  // turning faster than the motor's no-load speed (driven from outside; reported only)
};

// the mode a motor's driver is in (the seed's motor_error bits 30..31): reset while the MC does not
// drive it (passive command, or stopped on an error), motor mode while it runs a command
enum class MotorDriverMode : std::uint8_t { Reset = 0, Calibration = 1, Motor = 2, Brake = 3 };

inline constexpr std::uint32_t kMotorErrorBits = kMotorDisconnected | kMotorOverTemperature | kMotorDriverFault |
                                                 kMotorUnderVoltage | kMotorOverVoltage | kMotorOverCurrent |
                                                 kMotorEncoderLost | kMotorOverload;
inline constexpr std::uint32_t kMotorWarningBits = kMotorTemperatureWarning;

// "over-temperature, temperature warning": the names of the set bits, for people
inline std::string motor_fault_names(std::uint32_t faults) {
  static constexpr const char* kNames[] = {"disconnected",        "over-temperature", "driver fault", "under-voltage",
                                           "over-voltage",        "over-current",     "encoder lost", "overload",
                                           "temperature warning", "over-speed"};
  std::string names;
  for (std::size_t bit = 0; bit < sizeof kNames / sizeof kNames[0]; ++bit) {
    if ((faults & (1u << bit)) == 0) continue;
    if (!names.empty()) names += ", ";
    names += kNames[bit];
  }
  return names;
}

// what the battery management system reports
struct BatteryReading {
  bool present = false;  // false: the robot reports no battery (no battery protection)
  double voltage_v = 0.0;
  double current_a = 0.0;  // drawn from the pack (> 0 discharging)
  double state_of_charge_percent = 100.0;
};

}  // namespace cerebellum
