#include "io/common/motor_error_word.hpp"

#include <array>
#include <utility>

namespace cerebellum {
namespace {

// MotorFault bit -> the seed's bit (cyberdog2-highlevel.md section 5): over-current is reported
// as phase A (bit 17), overload as the first overload bit (9)
constexpr std::array<std::pair<std::uint32_t, std::uint32_t>, 9> kWordBits{{
    {kMotorDisconnected, 1u << 0},
    {kMotorOverTemperature, 1u << 1},
    {kMotorDriverFault, 1u << 2},
    {kMotorUnderVoltage, 1u << 3},
    {kMotorOverVoltage, 1u << 4},
    {kMotorEncoderLost, 1u << 8},
    {kMotorOverload, 1u << 9},
    {kMotorOverCurrent, 1u << 17},
    {kMotorTemperatureWarning, 1u << 24},
}};

}  // namespace

std::uint32_t motor_error_word(std::uint32_t motor_faults, MotorDriverMode mode) {
  std::uint32_t word = static_cast<std::uint32_t>(mode) << 30;
  for (const auto& [fault, bit] : kWordBits) {
    if (motor_faults & fault) word |= bit;
  }
  return word;
}

std::uint32_t motor_faults_from_word(std::uint32_t word) {
  std::uint32_t faults = kMotorOk;
  for (const auto& [fault, bit] : kWordBits) {
    if (word & bit) faults |= fault;
  }
  // the seed's other over-current and overload bits (phases B, C; overload 10..16)
  if (word & ((1u << 5) | (1u << 6))) faults |= kMotorOverCurrent;
  if (word & (0xFFu << 9) & ~(1u << 9)) faults |= kMotorOverload;
  return faults;
}

}  // namespace cerebellum
