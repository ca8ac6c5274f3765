// The faults the simulation can inject, in one small text grammar shared by the `cerebellum fault`
// verb, the simulation's control channel and the fault scenario files:
//   motor N disconnected | over_temperature | driver_fault | under_voltage | over_voltage |
//           over_current [A|B|C] | overload [1..8] | encoder_lost | stuck | derated FRACTION | hot DEG_C
//   imu bias RAD_S | stuck | dropout | nan
//   battery soc PERCENT | drain FACTOR | capacity AH | sag VOLTS
//   foot LEG slippery [MU]
//   clear [motor N | imu | battery | foot LEG]
// N is the motor in SDK order (0 FR abad, 1 FR hip, 2 FR knee, 3 FL abad, ... 11 RL knee) or its
// name (FR_knee); LEG is 0..3 or FR, FL, RR, RL. An over-current names the driver's phase (A when
// not given), an overload which of its eight overload bits (1 when not given). An optional
// "for SECONDS" ends a fault by itself.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace cerebellum {

enum class FaultTarget { Motor, Imu, Battery, Foot, All };

enum class FaultKind {
  Clear,
  // motor: the driver reports the condition and stops its motor
  Disconnected,
  OverTemperature,
  DriverFault,
  UnderVoltage,
  OverVoltage,
  OverCurrent,
  Overload,
  EncoderLost,
  // motor, silent: a seized joint, a weak motor
  Stuck,
  Derated,
  // motor: its coil reads at least this warm (deg C); the driver answers it as a real temperature
  Hot,
  // IMU
  ImuBias,
  ImuStuck,
  ImuDropout,
  ImuNan,
  // battery (as its management system reports it)
  BatteryStateOfCharge,
  BatteryDrain,
  BatteryCapacity,
  BatterySag,
  // foot
  Slippery,
};

struct FaultRequest {
  FaultTarget target = FaultTarget::All;
  int index = -1;  // the motor (0..11) or the leg (0..3); -1 for the IMU, the battery and "clear" of all
  FaultKind kind = FaultKind::Clear;
  // the kind's number (fraction, rad/s, %, factor, Ah, V, friction; the over-current's
  // phase as a MotorPhase, the overload's bit 1..8)
  double value = 0.0;
  double duration_s = 0.0;  // > 0: the fault ends by itself after this long; 0: until cleared
};

struct FaultParse {
  std::optional<FaultRequest> request;
  std::string error;  // when there is no request: what is wrong and what is accepted
};

// the words after "fault"
FaultParse parse_fault(const std::vector<std::string>& words);
FaultParse parse_fault(const std::string& text);
// the text parse_fault reads back as this request
std::string fault_text(const FaultRequest& request);
// the grammar, for --help and for refusals
const char* fault_grammar();

}  // namespace cerebellum
