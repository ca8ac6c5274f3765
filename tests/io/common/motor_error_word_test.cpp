// The seed's motor_error word: each condition at the bit the reference names, one translation for
// the response and the SDK's spi flags.
#include "io/common/motor_error_word.hpp"

#include <gtest/gtest.h>

#include <bit>

namespace cerebellum {
namespace {

TEST(MotorErrorWord, AHealthyMotorReadsMotorModeAndNoBits) {
  EXPECT_EQ(motor_error_word(kMotorOk, MotorDriverMode::Motor), 0x80000000u);
}

TEST(MotorErrorWord, TheDriversModeIsInBitsThirtyAndThirtyOne) {
  // the seed: 0 reset, 1 calibration, 2 motor mode, 3 brake
  EXPECT_EQ(motor_error_word(kMotorOk, MotorDriverMode::Reset), 0x00000000u);
  EXPECT_EQ(motor_error_word(kMotorOk, MotorDriverMode::Calibration), 0x40000000u);
  EXPECT_EQ(motor_error_word(kMotorOk, MotorDriverMode::Brake), 0xC0000000u);
  EXPECT_EQ(motor_error_word(kMotorDisconnected, MotorDriverMode::Reset), 0x00000001u);
}

TEST(MotorErrorWord, EachConditionSetsTheBitTheReferenceNames) {
  // cyberdog2-highlevel.md section 5: bit0 disconnected, bit1 coil over-temperature, bit2 driver
  // chip, bit3 under-voltage, bit4 over-voltage, bit5 phase-B over-current, bit6 phase-C
  // over-current, bit8 encoder, bits 9..16 overload, bit17 phase-A over-current, bit24
  // temperature warning
  EXPECT_EQ(motor_error_word(kMotorDisconnected, MotorDriverMode::Motor), 0x80000001u);
  EXPECT_EQ(motor_error_word(kMotorOverTemperature, MotorDriverMode::Motor), 0x80000002u);
  EXPECT_EQ(motor_error_word(kMotorDriverFault, MotorDriverMode::Motor), 0x80000004u);
  EXPECT_EQ(motor_error_word(kMotorUnderVoltage, MotorDriverMode::Motor), 0x80000008u);
  EXPECT_EQ(motor_error_word(kMotorOverVoltage, MotorDriverMode::Motor), 0x80000010u);
  EXPECT_EQ(motor_error_word(kMotorEncoderLost, MotorDriverMode::Motor), 0x80000100u);
  EXPECT_EQ(motor_error_word(motor_over_current(MotorPhase::A), MotorDriverMode::Motor), 0x80020000u);
  EXPECT_EQ(motor_error_word(motor_over_current(MotorPhase::B), MotorDriverMode::Motor), 0x80000020u);
  EXPECT_EQ(motor_error_word(motor_over_current(MotorPhase::C), MotorDriverMode::Motor), 0x80000040u);
  EXPECT_EQ(motor_error_word(motor_overload(1), MotorDriverMode::Motor), 0x80000200u);
  EXPECT_EQ(motor_error_word(motor_overload(8), MotorDriverMode::Motor), 0x80010000u);
  EXPECT_EQ(motor_error_word(kMotorTemperatureWarning, MotorDriverMode::Motor), 0x81000000u);
}

TEST(MotorErrorWord, EachOverloadKindHasItsOwnBitFromNineToSixteen) {
  for (int kind = 1; kind <= kMotorOverloadKinds; ++kind) {
    EXPECT_EQ(motor_error_word(motor_overload(kind), MotorDriverMode::Reset), 1u << (8 + kind)) << "overload " << kind;
  }
}

TEST(MotorErrorWord, EveryConditionTripsTheSdkExamplesMaskAndReadsBackAsItself) {
  // every MotorFault bit the word carries: one wire bit each, read back exactly (the phase, the
  // overload kind); over-speed has no bit in the word
  std::uint32_t wire_bits_used = 0;
  for (std::uint32_t bit = 1; bit <= kMotorTemperatureWarning; bit <<= 1) {
    const std::uint32_t word = motor_error_word(bit, MotorDriverMode::Motor);
    const std::uint32_t fault_bits = word & kMotorErrorWordFaultMask;
    EXPECT_EQ(std::popcount(fault_bits), 1) << "fault bit " << bit;
    EXPECT_EQ(wire_bits_used & fault_bits, 0u) << "fault bit " << bit << " shares its wire bit";
    wire_bits_used |= fault_bits;
    EXPECT_EQ(motor_faults_from_word(word), bit);
  }
  EXPECT_EQ(motor_error_word(kMotorOverSpeed, MotorDriverMode::Motor), kMotorErrorWordHealthy);
}

TEST(MotorErrorWord, EveryWireBitTheReferenceNamesReadsBackAsItselfAndNoOtherBitReadsAsAFault) {
  // the client side's view: each of the 30 bits below the mode alone on the wire
  // bits 0..6, 8 (encoder), 9..16 (overload), 17 (phase A), 24 (temperature warning)
  constexpr std::uint32_t kNamedBits = 0x7Fu | (0x3FFu << 8) | (1u << 24);
  for (unsigned wire_bit = 0; wire_bit < 30; ++wire_bit) {
    const std::uint32_t word = 0x80000000u | (1u << wire_bit);
    const std::uint32_t faults = motor_faults_from_word(word);
    if (kNamedBits & (1u << wire_bit)) {
      EXPECT_EQ(std::popcount(faults), 1) << "wire bit " << wire_bit;
      EXPECT_EQ(motor_error_word(faults, MotorDriverMode::Motor), word) << "wire bit " << wire_bit;
    } else {
      EXPECT_EQ(faults, kMotorOk) << "wire bit " << wire_bit;
    }
  }
  EXPECT_EQ(motor_faults_from_word(0x80000000u | (1u << 5)), kMotorOverCurrentPhaseB);
  EXPECT_EQ(motor_faults_from_word(0x80000000u | (1u << 6)), kMotorOverCurrentPhaseC);
  EXPECT_EQ(motor_faults_from_word(0x80000000u | (1u << 17)), kMotorOverCurrentPhaseA);
  EXPECT_EQ(motor_faults_from_word(0x80000000u | (1u << 12)), motor_overload(4));
}

}  // namespace
}  // namespace cerebellum

namespace cerebellum {
namespace {

TEST(MotorFaultNames, NameEachSetBitInOrder) {
  EXPECT_EQ(motor_fault_names(kMotorOk), "");
  EXPECT_EQ(motor_fault_names(kMotorOverTemperature | kMotorTemperatureWarning),
            "over-temperature, temperature warning");
  EXPECT_EQ(motor_fault_names(kMotorDisconnected | motor_overload(1)), "disconnected, overload 1");
  EXPECT_EQ(motor_fault_names(motor_over_current(MotorPhase::B) | motor_overload(8)),
            "over-current phase B, overload 8");
}

TEST(MotorFault, EveryPhaseAndEveryOverloadKindIsItsOwnBitAndCountsAsOverCurrentOrOverload) {
  std::uint32_t seen = 0;
  for (MotorPhase phase : {MotorPhase::A, MotorPhase::B, MotorPhase::C}) {
    const std::uint32_t bit = motor_over_current(phase);
    EXPECT_EQ(std::popcount(bit), 1);
    EXPECT_EQ(seen & bit, 0u);
    EXPECT_EQ(bit & ~kMotorOverCurrentAnyPhase, 0u);
    seen |= bit;
  }
  EXPECT_EQ(seen, kMotorOverCurrentAnyPhase);
  for (int kind = 1; kind <= kMotorOverloadKinds; ++kind) {
    const std::uint32_t bit = motor_overload(kind);
    EXPECT_EQ(std::popcount(bit), 1);
    EXPECT_EQ(seen & bit, 0u);
    EXPECT_EQ(bit & ~kMotorOverloadAny, 0u);
    seen |= bit;
  }
  EXPECT_EQ(seen, kMotorOverCurrentAnyPhase | kMotorOverloadAny);
  // all of them are errors: the driver stops its motor, the MC protects
  EXPECT_EQ(seen & ~kMotorErrorBits, 0u);
}

}  // namespace
}  // namespace cerebellum
