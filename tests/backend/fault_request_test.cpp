// The fault grammar shared by the verb, the channel and the scenario files: every fault reads
// back from its own text, bad input is refused with what is accepted.
#include "backend/fault_request.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/motor_health.hpp"

namespace cerebellum {
namespace {

FaultRequest parsed(const std::string& text) {
  const FaultParse result = parse_fault(text);
  EXPECT_TRUE(result.request.has_value()) << text << ": " << result.error;
  return result.request.value_or(FaultRequest{});
}

std::string refusal(const std::string& text) {
  const FaultParse result = parse_fault(text);
  EXPECT_FALSE(result.request.has_value()) << text;
  return result.error;
}

TEST(FaultRequest, MotorsAreNamedByIndexOrByLegAndJoint) {
  EXPECT_EQ(parsed("motor 3 disconnected").index, 3);
  EXPECT_EQ(parsed("motor FR_knee disconnected").index, 2);
  EXPECT_EQ(parsed("motor RL_abad encoder_lost").index, 9);
  const FaultRequest derated = parsed("motor 11 derated 0.4 for 2.5");
  EXPECT_EQ(derated.target, FaultTarget::Motor);
  EXPECT_EQ(derated.kind, FaultKind::Derated);
  EXPECT_EQ(derated.value, 0.4);
  EXPECT_EQ(derated.duration_s, 2.5);
}

TEST(FaultRequest, EveryFaultReadsBackFromItsText) {
  for (const char* text : {"motor 0 disconnected", "motor 1 over_temperature",
                           "motor 2 driver_fault", "motor 3 under_voltage",
                           "motor 4 over_voltage", "motor 5 over_current B",
                           "motor 6 overload 8",   "motor 7 encoder_lost",
                           "motor 8 stuck",        "motor 9 derated 0.5",
                           "motor 10 hot 78",
                           "imu bias -0.02",       "imu stuck",
                           "imu dropout",          "imu nan",
                           "battery soc 15",       "battery drain 20",
                           "battery capacity 1.5", "battery sag 3",
                           "foot 2 slippery 0.1",  "clear",
                           "clear motor 4",        "clear imu",
                           "clear battery",        "clear foot 1",
                           "imu stuck for 0.5"}) {
    const FaultRequest request = parsed(text);
    EXPECT_EQ(fault_text(request), text);
  }
  // a slippery foot's friction has a default
  EXPECT_EQ(parsed("foot RR slippery").value, 0.05);
}

TEST(FaultRequest, AnOverCurrentNamesItsPhaseAndAnOverloadItsBitWithPhaseAAndBitOneWhenNotGiven) {
  EXPECT_EQ(parsed("motor 5 over_current").value, static_cast<double>(MotorPhase::A));
  EXPECT_EQ(parsed("motor 5 over_current A").value, static_cast<double>(MotorPhase::A));
  EXPECT_EQ(parsed("motor 5 over_current B").value, static_cast<double>(MotorPhase::B));
  EXPECT_EQ(parsed("motor 5 over_current C for 2").value, static_cast<double>(MotorPhase::C));
  EXPECT_EQ(fault_text(parsed("motor 5 over_current")), "motor 5 over_current A");
  EXPECT_EQ(parsed("motor 6 overload").value, 1.0);
  EXPECT_EQ(parsed("motor 6 overload 8").value, 8.0);
  EXPECT_EQ(fault_text(parsed("motor 6 overload")), "motor 6 overload 1");
  for (const char* text : {"motor 0 over_current A", "motor 0 over_current B", "motor 0 over_current C"}) {
    EXPECT_EQ(fault_text(parsed(text)), text);
  }
  for (int kind = 1; kind <= 8; ++kind) {
    const std::string text = "motor 0 overload " + std::to_string(kind);
    EXPECT_EQ(fault_text(parsed(text)), text);
  }
  EXPECT_NE(refusal("motor 5 over_current D").find("over_current value must be A|B|C, got 'D'"), std::string::npos);
  EXPECT_NE(refusal("motor 5 over_current b").find("must be A|B|C"), std::string::npos);
  EXPECT_NE(refusal("motor 5 over_current AB").find("must be A|B|C"), std::string::npos);
  EXPECT_NE(refusal("motor 6 overload 0").find("overload value must be a whole number in [1, 8], got '0'"),
            std::string::npos);
  EXPECT_NE(refusal("motor 6 overload 9").find("[1, 8]"), std::string::npos);
  EXPECT_NE(refusal("motor 6 overload 2.5").find("a whole number"), std::string::npos);
  EXPECT_NE(refusal("motor 6 overload B").find("a whole number"), std::string::npos);
}

TEST(FaultRequest, BadInputIsRefusedWithWhatIsAccepted) {
  EXPECT_NE(refusal("").find("no fault given"), std::string::npos);
  EXPECT_NE(refusal("wheel 2 flat").find("unknown component 'wheel' (accepted: motor, imu, battery, foot, clear)"),
            std::string::npos);
  EXPECT_NE(refusal("motor 12 disconnected").find("motor must be 0..11"), std::string::npos);
  EXPECT_NE(refusal("motor 1.5 disconnected").find("motor must be 0..11"), std::string::npos);
  EXPECT_NE(refusal("motor 3 hot 150").find("120"), std::string::npos);
  EXPECT_NE(refusal("motor 3 melted").find("unknown motor fault 'melted' (accepted: disconnected,"), std::string::npos);
  EXPECT_NE(refusal("motor 3 derated").find("needs a value in [0, 1]"), std::string::npos);
  EXPECT_NE(refusal("motor 3 derated 1.5").find("must be a number in [0, 1], got '1.5'"), std::string::npos);
  EXPECT_NE(refusal("motor 3 derated nan").find("must be a number"), std::string::npos);
  EXPECT_NE(refusal("imu stuck 3").find("takes no value"), std::string::npos);
  EXPECT_NE(refusal("battery soc 150").find("[0, 100]"), std::string::npos);
  EXPECT_NE(refusal("imu stuck for -1").find("for SECONDS must be in (0, 3600]"), std::string::npos);
  EXPECT_NE(refusal("clear for 3").find("clear takes no duration"), std::string::npos);
  EXPECT_NE(refusal("clear wheel").find("clear what"), std::string::npos);
  EXPECT_NE(refusal("foot 4 slippery").find("leg must be 0..3"), std::string::npos);
}

}  // namespace
}  // namespace cerebellum
