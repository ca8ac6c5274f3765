// What the safety stage found wrong in one cycle. The checks fill it; the state machine and the
// loop react to it (safety decides what is wrong, the machine what to do about it).
#pragma once

#include <cstdint>

namespace cerebellum {

// what the guard did to a joint command, one bit per cause
enum GuardFlag : std::uint32_t {
  kGuardOk = 0,
  kGuardClampedGain = 1u << 0,
  kGuardClampedTorque = 1u << 1,
  kGuardClampedVelocity = 1u << 2,
  kGuardClampedPosition = 1u << 3,
  kGuardNonFiniteCommand = 1u << 4,  // command replaced by damping
  kGuardInvalidState = 1u << 5,      // state not trusted: command replaced by damping
  kGuardHealthDamping = 1u << 6,     // the health protection damps: command replaced by damping
  kGuardHealthStopped = 1u << 7,     // the health protection stopped the motors: passive command
};

struct SafetyReport {
  std::uint32_t flags = kGuardOk;  // GuardFlag bits of the command guard
  bool orientation_error = false;  // |roll| or |pitch| at or beyond the limit
  int footpos_error = 0;           // bit 3 * leg + axis: a foot outside its workspace
  bool lifted = false;             // picked up (the lift watch of a standing mode)
  bool landed = false;             // set down again (the lift watch while lifted)

  bool replaced() const {
    return (flags & (kGuardNonFiniteCommand | kGuardInvalidState | kGuardHealthDamping | kGuardHealthStopped)) != 0;
  }
  // the body is in a state the machine must stop for
  bool body_fault() const { return orientation_error || footpos_error != 0; }
};

}  // namespace cerebellum
