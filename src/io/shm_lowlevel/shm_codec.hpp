// Translation between the lowlevel.h structs and the MC's value types: SDK joint convention on
// both sides (no sign flip), legs FR, FL, RR, RL, the unused foot joint zeroed or ignored.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/robot_readings.hpp"
#include "core/types.hpp"
#include "lowlevel/lowlevel.h"

namespace cerebellum {

// the bus voltage reported by a robot without a battery reading: the pack's nominal 24 V
inline constexpr double kShmNominalBusVoltageV = 24.0;

// bit0 enabled (cleared while the motor's driver is stopped by an error), bits 1..5 the faults
// lowlevel.h names (MotorFault bits without an own flag show only as "not enabled"), bits 8..15
// temperature + 40 (clamped to -40..215 deg C), bits 16..23 bus voltage (whole volts, 0..255)
// driver_mode: bit 0 (enabled) only in motor mode
std::int32_t shm_joint_state_flags(double temperature_c, std::uint32_t motor_faults, double bus_voltage_v,
                                   MotorDriverMode driver_mode = MotorDriverMode::Motor);

// state.legs of one frame
void encode_shm_legs(const SensorFrame& frame, leg_state_t (&legs)[kNumLegs]);
// the IMU of one frame: acc the accelerometer as it reads (specific force, gravity included: +9.81
// on z at rest), body frame; timestamp: robot time in ns
void encode_shm_imu(const SensorFrame& frame, nav_imu_t& imu);
std::uint64_t shm_timestamp_ns(double time_s);

// cmd.legs -> command, every value as the client wrote it (the foot entries and leg flags are
// not read): whether the motors may run it is the source's decision
// (lowlevel/shm/shm_command_rules.hpp), not the translation's
JointCommand decode_shm_command(const leg_control_t (&legs)[kNumLegs]);

// the client's side (the MC driving a ZsiBot through its daemon, io/shm_lowlevel_robot): the
// inverses of the daemon's encoders. The joints from state.legs: temperature from bits 8..15,
// each fault bit lowlevel.h names as its MotorFault (an over-current as every phase: the header
// does not name the phase), a motor not enabled as a driver in reset. A fault the header has no
// bit for shows only as "not enabled" and cannot be told from a motor the daemon keeps off.
JointReading decode_shm_legs(const leg_state_t (&legs)[kNumLegs]);
MotorDriverMode shm_driver_mode(std::int32_t flags);
std::uint32_t shm_motor_faults(std::int32_t flags);
double shm_temperature_c(std::int32_t flags);
// the IMU as nav_imu_t carries it (acc is the specific force, +9.81 on z at rest)
ImuReading decode_shm_imu(const nav_imu_t& imu);
// a command frame as a client writes cmd.legs: each leg's flags 1, the foot joint zero
void encode_shm_command(const JointCommand& command, leg_control_t (&legs)[kNumLegs]);

}  // namespace cerebellum
