// The jump gate: when the robot may leave the ground, and the flips' temperature and battery
// gates of the reference (switch_status 6 and 7), on states built by hand.
#include "safety/jump_gate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace cerebellum {
namespace {

// standing still, level, on four loaded feet, healthy, on a charged battery
RobotState standing() {
  RobotState state;
  state.valid = true;
  state.height_m = 0.235;
  state.contact = {1.0, 1.0, 1.0, 1.0};
  state.temperature_c.fill(40.0);
  state.battery.present = true;
  state.battery.state_of_charge_percent = 80.0;
  return state;
}

std::string refusal(const RobotState& state) {
  const char* reason = jump_refusal(state);
  return reason != nullptr ? reason : "";
}

TEST(JumpGate, AStillLevelHealthyStandMayJump) { EXPECT_EQ(jump_refusal(standing()), nullptr); }

TEST(JumpGate, MovingTurningTiltedSlopedLyingOrLiftedFeetAreRefusedEachWithItsReason) {
  RobotState moving = standing();
  moving.velocity_world = {0.35, 0.0, 0.0};
  EXPECT_NE(refusal(moving).find("faster than 0.3 m/s"), std::string::npos);
  moving.velocity_world = {0.2, 0.2, 0.0};  // 0.28 m/s
  EXPECT_EQ(jump_refusal(moving), nullptr);

  RobotState turning = standing();
  turning.omega_world = {0.0, 0.0, 0.6};
  EXPECT_NE(refusal(turning).find("turning"), std::string::npos);

  RobotState tilted = standing();
  tilted.rpy = {0.0, 0.3, 0.0};
  EXPECT_NE(refusal(tilted).find("tilted"), std::string::npos);

  RobotState sloped = standing();
  sloped.ground.gradient = {0.12, 0.0};  // about 7 deg
  EXPECT_NE(refusal(sloped).find("slope"), std::string::npos);
  sloped.ground.gradient = {0.05, 0.05};  // about 4 deg
  EXPECT_EQ(jump_refusal(sloped), nullptr);

  RobotState lying = standing();
  lying.height_m = 0.1;
  EXPECT_NE(refusal(lying).find("not standing"), std::string::npos);

  RobotState three_feet = standing();
  three_feet.contact[2] = 0.0;
  EXPECT_NE(refusal(three_feet).find("four feet"), std::string::npos);
}

TEST(JumpGate, AMotorFaultOrAnUntrustedStateIsRefused) {
  RobotState faulty = standing();
  faulty.motor_faults[4] = kMotorTemperatureWarning;
  EXPECT_NE(refusal(faulty).find("motor"), std::string::npos);
  RobotState unknown = standing();
  unknown.valid = false;
  EXPECT_NE(refusal(unknown).find("cannot be trusted"), std::string::npos);
}

TEST(JumpGate, AFlipNeedsEveryMotorAtOrBelowSeventyFourDegrees) {
  RobotState state = standing();
  state.temperature_c[7] = 74.0;
  EXPECT_EQ(flip_gate(state, Flip::Back), FlipGate::Allowed);
  state.temperature_c[7] = 74.1;
  EXPECT_EQ(flip_gate(state, Flip::Back), FlipGate::OverHeat);
  EXPECT_EQ(flip_gate(state, Flip::Front), FlipGate::OverHeat);
  state.temperature_c[7] = std::nan("");  // a reading that cannot be trusted is not cool
  EXPECT_EQ(flip_gate(state, Flip::Back), FlipGate::OverHeat);
}

TEST(JumpGate, AFrontFlipNeedsHalfTheBatteryABackFlipAFifth) {
  RobotState state = standing();
  state.battery.state_of_charge_percent = 50.0;
  EXPECT_EQ(flip_gate(state, Flip::Front), FlipGate::Allowed);
  state.battery.state_of_charge_percent = 49.9;
  EXPECT_EQ(flip_gate(state, Flip::Front), FlipGate::LowBattery);
  EXPECT_EQ(flip_gate(state, Flip::Back), FlipGate::Allowed);
  state.battery.state_of_charge_percent = 19.9;
  EXPECT_EQ(flip_gate(state, Flip::Back), FlipGate::LowBattery);
  // hot and low: the temperature is said first
  state.temperature_c[0] = 80.0;
  EXPECT_EQ(flip_gate(state, Flip::Back), FlipGate::OverHeat);
  // a robot without a battery reading (a bench supply) has no battery gate
  RobotState supplied = standing();
  supplied.battery.present = false;
  supplied.battery.state_of_charge_percent = 0.0;
  EXPECT_EQ(flip_gate(supplied, Flip::Front), FlipGate::Allowed);
}

}  // namespace
}  // namespace cerebellum
