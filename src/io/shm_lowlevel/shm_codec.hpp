// Translation between the lowlevel.h structs and the MC's value types: SDK joint convention on
// both sides (no sign flip), legs FR, FL, RR, RL, the unused foot joint zeroed or ignored.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/types.hpp"
#include "lowlevel/lowlevel.h"

namespace cerebellum {

inline constexpr std::int32_t kShmBusVoltageV = 24;

// bit0 enabled, bits 8..15 temperature + 40 (clamped to -40..215 deg C), bits 16..23 bus voltage
std::int32_t shm_joint_state_flags(double temperature_c);

// state.legs of one frame
void encode_shm_legs(const SensorFrame& frame, leg_state_t (&legs)[kNumLegs]);
// the IMU of one frame; timestamp: robot time in ns
void encode_shm_imu(const SensorFrame& frame, nav_imu_t& imu);
std::uint64_t shm_timestamp_ns(double time_s);

enum class ShmCommandFault { None, NonFinite, GainOutOfRange };
enum class ShmCommandField { PDes, VDes, Kp, Kd, TFf };

// why a command frame was rejected: the first offending value
struct ShmCommandCheck {
  ShmCommandFault fault = ShmCommandFault::None;
  std::size_t joint = 0;  // joint_index order
  ShmCommandField field = ShmCommandField::PDes;
  double value = 0.0;
  bool ok() const { return fault == ShmCommandFault::None; }
};

// gains outside these bounds are a client bug, not something to clamp
struct ShmGainBounds {
  double kp_max = 200.0;
  double kd_max = 10.0;
};

// cmd.legs -> command (the foot entries and leg flags are not read). Rejects the frame when a
// value is NaN/Inf or a gain is negative or above its bound; command is then left untouched.
ShmCommandCheck decode_shm_command(const leg_control_t (&legs)[kNumLegs], const ShmGainBounds& bounds,
                                   JointCommand& command);

const char* shm_command_field_name(ShmCommandField field);

}  // namespace cerebellum
