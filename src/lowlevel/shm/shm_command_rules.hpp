// The rules a shared-memory command frame must pass before the motors run it: no NaN/Inf and
// gains inside their ranges. A frame that fails is a client bug: it is rejected, not clamped.
#pragma once

#include <cstddef>

#include "core/types.hpp"
#include "safety/command_limits.hpp"

namespace cerebellum {

enum class ShmCommandFault { None, NonFinite, GainOutOfRange };
// the fields of leg_control_t, in the order of JointCommand's fields (safety/command_finite.hpp)
enum class ShmCommandField { PDes, VDes, Kp, Kd, TFf };

// why a command frame was rejected: the first offending value
struct ShmCommandCheck {
  ShmCommandFault fault = ShmCommandFault::None;
  std::size_t joint = 0;  // joint_index order
  ShmCommandField field = ShmCommandField::PDes;
  double value = 0.0;
  bool ok() const { return fault == ShmCommandFault::None; }
};

// joint by joint: the first NaN/Inf, or a kp outside [0, kp_max] or kd outside [0, kd_max]
ShmCommandCheck check_shm_command(const JointCommand& command, const CommandLimits& limits);

const char* shm_command_field_name(ShmCommandField field);

}  // namespace cerebellum
