#include "io/common/motor_error_word.hpp"

#include <array>
#include <utility>

namespace cerebellum {
namespace {

using BitPair = std::pair<std::uint32_t, std::uint32_t>;
constexpr std::size_t kSingleBits = 10;

// MotorFault bit -> the seed's bit (cyberdog2-highlevel.md section 5): over-current by its phase
// (A 17, B 5, C 6), overload kind k at bit 8 + k (9..16)
constexpr std::array<BitPair, kSingleBits + kMotorOverloadKinds> kWordBits = [] {
  std::array<BitPair, kSingleBits + kMotorOverloadKinds> bits{{
      {kMotorDisconnected, 1u << 0},
      {kMotorOverTemperature, 1u << 1},
      {kMotorDriverFault, 1u << 2},
      {kMotorUnderVoltage, 1u << 3},
      {kMotorOverVoltage, 1u << 4},
      {kMotorOverCurrentPhaseB, 1u << 5},
      {kMotorOverCurrentPhaseC, 1u << 6},
      {kMotorEncoderLost, 1u << 8},
      {kMotorOverCurrentPhaseA, 1u << 17},
      {kMotorTemperatureWarning, 1u << 24},
  }};
  for (int kind = 1; kind <= kMotorOverloadKinds; ++kind) {
    bits[kSingleBits + static_cast<std::size_t>(kind - 1)] = {motor_overload(kind), 1u << (8 + kind)};
  }
  return bits;
}();

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
  return faults;
}

}  // namespace cerebellum
