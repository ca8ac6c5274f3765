// What the robot's power and motor drivers report about themselves, in the MC's own terms; the
// interface adapters translate these bits into each wire format (motor_error, spi flags,
// joint_state_t.flags).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace cerebellum {

// per motor, one bit per condition its driver reports; the driver names the phase of an
// over-current and raises one of eight overload bits (the reference does not tell those apart),
// so each has a bit of its own here and the interfaces report exactly the one raised
enum MotorFault : std::uint32_t {
  kMotorOk = 0,
  kMotorDisconnected = 1u << 0,     // no answer from the driver
  kMotorOverTemperature = 1u << 1,  // coil at or above the shutdown temperature: the driver stops
  kMotorDriverFault = 1u << 2,      // driver chip
  kMotorUnderVoltage = 1u << 3,     // bus voltage below the driver's limit
  kMotorOverVoltage = 1u << 4,
  kMotorOverCurrentPhaseA = 1u << 5,
  kMotorOverCurrentPhaseB = 1u << 6,
  kMotorOverCurrentPhaseC = 1u << 7,
  kMotorEncoderLost = 1u << 8,          // the position sensor does not answer or is not calibrated
  kMotorOverload1 = 1u << 9,            // the first of eight overload bits, 9..16: motor_overload(k)
  kMotorTemperatureWarning = 1u << 17,  // coil at or above the warning temperature (not an error)
  kMotorOverSpeed = 1u << 18,  // turning faster than the motor's no-load speed (driven from outside; reported only)
};

enum class MotorPhase : std::uint8_t { A = 0, B = 1, C = 2 };
inline constexpr int kMotorOverloadKinds = 8;

// an over-current in any phase, an overload of any kind: what the protections and the interfaces
// without a bit per phase or per kind test
inline constexpr std::uint32_t kMotorOverCurrentAnyPhase =
    kMotorOverCurrentPhaseA | kMotorOverCurrentPhaseB | kMotorOverCurrentPhaseC;
inline constexpr std::uint32_t kMotorOverloadAny = ((1u << kMotorOverloadKinds) - 1u) * kMotorOverload1;

constexpr std::uint32_t motor_over_current(MotorPhase phase) {
  return kMotorOverCurrentPhaseA << static_cast<unsigned>(phase);
}
// kind 1..kMotorOverloadKinds
constexpr std::uint32_t motor_overload(int kind) { return kMotorOverload1 << (kind - 1); }

// the mode a motor's driver is in (the seed's motor_error bits 30..31): reset while the MC does not
// drive it (passive command, or stopped on an error), motor mode while it runs a command
enum class MotorDriverMode : std::uint8_t { Reset = 0, Calibration = 1, Motor = 2, Brake = 3 };

inline constexpr std::uint32_t kMotorErrorBits = kMotorDisconnected | kMotorOverTemperature | kMotorDriverFault |
                                                 kMotorUnderVoltage | kMotorOverVoltage | kMotorOverCurrentAnyPhase |
                                                 kMotorEncoderLost | kMotorOverloadAny;
inline constexpr std::uint32_t kMotorWarningBits = kMotorTemperatureWarning;

// "over-temperature, temperature warning": the names of the set bits, for people
inline std::string motor_fault_names(std::uint32_t faults) {
  static constexpr const char* kNames[] = {
      "disconnected",         "over-temperature",     "driver fault",         "under-voltage", "over-voltage",
      "over-current phase A", "over-current phase B", "over-current phase C", "encoder lost",  "overload 1",
      "overload 2",           "overload 3",           "overload 4",           "overload 5",    "overload 6",
      "overload 7",           "overload 8",           "temperature warning",  "over-speed"};
  static_assert(1u << (sizeof kNames / sizeof kNames[0] - 1) == kMotorOverSpeed, "a name for every MotorFault bit");
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
