// The seed's motor_error word: each condition at the bit the reference names, one translation for
// the response and the SDK's spi flags.
#include "io/common/motor_error_word.hpp"

#include <gtest/gtest.h>

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
  // chip, bit3 under-voltage, bit4 over-voltage, bit8 encoder, bits 9..16 overload, bit17 phase-A
  // over-current, bit24 temperature warning
  EXPECT_EQ(motor_error_word(kMotorDisconnected, MotorDriverMode::Motor), 0x80000001u);
  EXPECT_EQ(motor_error_word(kMotorOverTemperature, MotorDriverMode::Motor), 0x80000002u);
  EXPECT_EQ(motor_error_word(kMotorDriverFault, MotorDriverMode::Motor), 0x80000004u);
  EXPECT_EQ(motor_error_word(kMotorUnderVoltage, MotorDriverMode::Motor), 0x80000008u);
  EXPECT_EQ(motor_error_word(kMotorOverVoltage, MotorDriverMode::Motor), 0x80000010u);
  EXPECT_EQ(motor_error_word(kMotorEncoderLost, MotorDriverMode::Motor), 0x80000100u);
  EXPECT_EQ(motor_error_word(kMotorOverload, MotorDriverMode::Motor), 0x80000200u);
  EXPECT_EQ(motor_error_word(kMotorOverCurrent, MotorDriverMode::Motor), 0x80020000u);
  EXPECT_EQ(motor_error_word(kMotorTemperatureWarning, MotorDriverMode::Motor), 0x81000000u);
}

TEST(MotorErrorWord, EveryConditionTripsTheSdkExamplesMaskAndReadsBack) {
  for (std::uint32_t bit = 1; bit <= kMotorTemperatureWarning; bit <<= 1) {
    const std::uint32_t word = motor_error_word(bit, MotorDriverMode::Motor);
    EXPECT_NE(word & kMotorErrorWordFaultMask, 0u) << "fault bit " << bit;
    EXPECT_EQ(motor_faults_from_word(word), bit);
  }
  EXPECT_EQ(motor_faults_from_word(0x80000000u | (1u << 6)), kMotorOverCurrent);  // phase C
  EXPECT_EQ(motor_faults_from_word(0x80000000u | (1u << 12)), kMotorOverload);
}

}  // namespace
}  // namespace cerebellum

namespace cerebellum {
namespace {

TEST(MotorFaultNames, NameEachSetBitInOrder) {
  EXPECT_EQ(motor_fault_names(kMotorOk), "");
  EXPECT_EQ(motor_fault_names(kMotorOverTemperature | kMotorTemperatureWarning),
            "over-temperature, temperature warning");
  EXPECT_EQ(motor_fault_names(kMotorDisconnected | kMotorOverload), "disconnected, overload");
}

}  // namespace
}  // namespace cerebellum
