// The seed's per-motor status word (robot_control_response.motor_error and spi_data.flags, both
// "as motor_error in 2.3.1"): the MC's MotorFault bits in the vendor's bit positions, the motor
// mode in bits 30..31. One home for the translation so both channels report a motor the same way.
#pragma once

#include <cstdint>

#include "core/motor_health.hpp"

namespace cerebellum {

// mode bits 30..31 = 2 (motor mode): a healthy running motor reads exactly this
inline constexpr std::uint32_t kMotorErrorWordHealthy = 0x80000000u;
// the bits a client tests for an error or a warning (the SDK example's mask)
inline constexpr std::uint32_t kMotorErrorWordFaultMask = 0x3FFFFFFFu;

// the driver's mode in bits 30..31 (the seed: 0 reset, 1 calibration, 2 motor mode, 3 brake)
std::uint32_t motor_error_word(std::uint32_t motor_faults, MotorDriverMode mode);
// back to MotorFault bits (the client verbs and tests read the wire with it)
std::uint32_t motor_faults_from_word(std::uint32_t word);
// the driver's mode from bits 30..31 (a robot backend reads the wire with it)
inline MotorDriverMode motor_driver_mode_from_word(std::uint32_t word) {
  return static_cast<MotorDriverMode>((word >> 30) & 0x3u);
}

}  // namespace cerebellum
