// The sim_command text: what a push is, its limits, and the refusals' words.
#include "io/lcm_sim_control/sim_command_text.hpp"

#include <gtest/gtest.h>

namespace cerebellum {
namespace {

std::string error_of(const std::string& text) {
  const SimCommand command = parse_sim_command(text);
  EXPECT_FALSE(command.push) << text;
  return command.error;
}

TEST(SimCommandText, ReadsAPushAndWritesItBackExactly) {
  const SimCommand command = parse_sim_command("push 12.5 -40 0.25 0.3");
  ASSERT_TRUE(command.push) << command.error;
  EXPECT_EQ(command.push->force_n, (std::array<double, 3>{12.5, -40.0, 0.25}));
  EXPECT_EQ(command.push->duration_s, 0.3);
  const ForcePulse odd{{1.0 / 3.0, -2.0 / 7.0, 1e-5}, 0.1};
  const SimCommand back = parse_sim_command(push_command_text(odd));
  ASSERT_TRUE(back.push) << back.error;
  EXPECT_EQ(back.push->force_n, odd.force_n);
  EXPECT_EQ(back.push->duration_s, odd.duration_s);
}

TEST(SimCommandText, RefusesWhatIsNotAPushOrAFaultNamingTheWord) {
  EXPECT_NE(error_of("").find("empty command"), std::string::npos);
  EXPECT_NE(error_of("shove 1 2 3 4").find("unknown command 'shove' (accepted: push FX FY FZ DURATION_S, fault ...)"),
            std::string::npos);
  EXPECT_NE(error_of("fault imu wobble").find("unknown imu fault 'wobble'"), std::string::npos);
  EXPECT_NE(error_of("push 1 2 3").find("push takes 4 numbers"), std::string::npos);
  EXPECT_NE(error_of("push 1 2 3 4 5").find("got 5"), std::string::npos);
  EXPECT_NE(error_of("push 1 x 3 0.1").find("push FY must be a finite number, got 'x'"), std::string::npos);
  EXPECT_NE(error_of("push nan 0 0 0.1").find("push FX must be a finite number, got 'nan'"), std::string::npos);
  EXPECT_NE(error_of("push 0 0 inf 0.1").find("push FZ must be a finite number"), std::string::npos);
  EXPECT_NE(error_of("push 0 0 1 1e400").find("DURATION_S must be a finite number"), std::string::npos);
  EXPECT_NE(error_of("push 1 2 3 0.1abc").find("DURATION_S must be a finite number, got '0.1abc'"), std::string::npos);
}

TEST(SimCommandText, AFaultCommandCarriesTheFaultAndReadsBack) {
  const SimCommand command = parse_sim_command("fault battery sag 2.5 for 3");
  ASSERT_TRUE(command.fault.has_value()) << command.error;
  EXPECT_FALSE(command.push.has_value());
  EXPECT_EQ(command.fault->kind, FaultKind::BatterySag);
  EXPECT_EQ(fault_command_text(*command.fault), "fault battery sag 2.5 for 3");
}

TEST(SimCommandText, KeepsForceAndDurationWithinTheirLimits) {
  // each component below the limit, the magnitude above it
  EXPECT_NE(error_of("push 300 300 300 0.1").find("push force 519.6"), std::string::npos);
  EXPECT_NE(error_of("push 300 300 300 0.1").find("above the limit of 500 N"), std::string::npos);
  EXPECT_TRUE(parse_sim_command("push 300 400 0 0.1").push);  // exactly 500 N
  EXPECT_NE(error_of("push 1 0 0 0").find("DURATION_S must be in (0, 10] s, got 0"), std::string::npos);
  EXPECT_NE(error_of("push 1 0 0 -1").find("got -1"), std::string::npos);
  EXPECT_NE(error_of("push 1 0 0 10.5").find("got 10.5"), std::string::npos);
  EXPECT_TRUE(parse_sim_command("push 1 0 0 10").push);
  EXPECT_NE(error_of("push 1 0 0 0.1" + std::string(300, ' ')).find("longer than 256 bytes"), std::string::npos);
}

}  // namespace
}  // namespace cerebellum
