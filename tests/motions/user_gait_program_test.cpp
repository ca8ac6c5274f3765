// From uploaded user gait files to the program the MC runs: the packed fields decoded as the
// reference says (with their fallbacks), and the gaits that are unsafe to run refused with why.
#include "motions/user_gait_program.hpp"

#include <gtest/gtest.h>

#include "modes/command_ranges.hpp"

namespace cerebellum {
namespace {

HighLevelCommand user_step(int duration_ms = 300) {
  HighLevelCommand step;
  step.mode = 11;
  step.gait_id = 110;
  step.duration = duration_ms;
  return step;
}

TEST(UserGaitStepDecoding, StepHeightsUnpackFromMillimetresPairs) {
  HighLevelCommand step = user_step();
  step.step_height = {51.0f + 1000.0f * 11.0f, 8.0f + 1000.0f * 60.0f};  // FR 51, FL 11, RR 8, RL 60 mm
  const UserGaitStep decoded = decode_user_gait_step(step);
  EXPECT_DOUBLE_EQ(decoded.legs.step_height_m[0], 0.051);
  EXPECT_DOUBLE_EQ(decoded.legs.step_height_m[1], 0.011);
  EXPECT_DOUBLE_EQ(decoded.legs.step_height_m[2], 0.008);
  EXPECT_DOUBLE_EQ(decoded.legs.step_height_m[3], 0.060);
  // 999 mm is far above a leg's reach: clamped
  step.step_height = {999.0f, 0.0f};
  EXPECT_DOUBLE_EQ(decode_user_gait_step(step).legs.step_height_m[0], UserGaitRanges{}.step_height.upper);
}

TEST(UserGaitStepDecoding, LandingPointsComeFromFootPoseAndCtrlPoint) {
  HighLevelCommand step = user_step();
  step.foot_pose = {0.01f, 0.02f, 0.03f, 0.04f, 0.05f, 0.06f};
  step.ctrl_point = {0.07f, -0.01f, 0.5f};
  const UserGaitStep decoded = decode_user_gait_step(step);
  EXPECT_FLOAT_EQ(decoded.legs.landing_offset_m[0].x(), 0.01f);
  EXPECT_FLOAT_EQ(decoded.legs.landing_offset_m[1].y(), 0.04f);
  EXPECT_FLOAT_EQ(decoded.legs.landing_offset_m[2].x(), 0.05f);
  EXPECT_FLOAT_EQ(decoded.legs.landing_offset_m[3].x(), 0.07f);
  EXPECT_FLOAT_EQ(decoded.legs.landing_offset_m[3].y(), -0.01f);
  EXPECT_FLOAT_EQ(decoded.legs.friction, 0.5f);
}

TEST(UserGaitStepDecoding, LandingGainAndFrictionFallBackOutsideTheirRanges) {
  HighLevelCommand step = user_step();
  step.contact = 15;  // 1.5
  EXPECT_DOUBLE_EQ(decode_user_gait_step(step).legs.landing_gain, 1.5);
  step.contact = 0;  // 0.0 is outside [0.01, 10]: 1.0
  EXPECT_DOUBLE_EQ(decode_user_gait_step(step).legs.landing_gain, 1.0);
  step.contact = -20;
  EXPECT_DOUBLE_EQ(decode_user_gait_step(step).legs.landing_gain, 1.0);
  step.ctrl_point[2] = 3.0f;  // mu 3: not sane, the MPC's own
  EXPECT_DOUBLE_EQ(decode_user_gait_step(step).legs.friction, 0.0);
}

TEST(UserGaitStepDecoding, HeightZeroMeansTheDefaultAndPoseIsClamped) {
  HighLevelCommand step = user_step();
  EXPECT_DOUBLE_EQ(decode_user_gait_step(step).height_m, kDefaultBodyHeightM);
  step.pos_des[2] = 0.5f;
  step.rpy_des = {1.0f, -1.0f, 0.1f};
  const UserGaitStep decoded = decode_user_gait_step(step);
  EXPECT_DOUBLE_EQ(decoded.height_m, UserGaitRanges{}.height.upper);
  EXPECT_DOUBLE_EQ(decoded.legs.roll_rad, UserGaitRanges{}.roll.upper);
  // -1 is the most head-down pitch the range allows: a right-handed pitch the other way
  EXPECT_DOUBLE_EQ(decoded.pitch_rad, -UserGaitRanges{}.pitch.lower);
  EXPECT_FLOAT_EQ(decoded.legs.yaw_offset_rad, 0.1f);
}

TEST(UserGaitStepDecoding, BodyPositionXYMovesTheBodyOverTheStepOnlyWhereNoVelocityIsGiven) {
  HighLevelCommand step = user_step(500);
  step.pos_des = {0.05f, -0.02f, 0.0f};  // body_pos_des x, y as the seed's converter places them
  UserGaitStep decoded = decode_user_gait_step(step);
  EXPECT_FLOAT_EQ(decoded.position_offset_m.x(), 0.05f);
  EXPECT_FLOAT_EQ(decoded.position_offset_m.y(), -0.02f);
  // 0.05 m in 0.5 s: steered at 0.1 m/s forward, -0.04 m/s sideways
  EXPECT_NEAR(decoded.body_velocity().x(), 0.1, 1e-6);
  EXPECT_NEAR(decoded.body_velocity().y(), -0.04, 1e-6);
  // a velocity on x makes the x position the integral of it (the seed: "in this direction"); y still moves
  step.vel_des = {0.2f, 0.0f, 0.0f};
  decoded = decode_user_gait_step(step);
  EXPECT_EQ(decoded.position_offset_m.x(), 0.0);
  EXPECT_NEAR(decoded.body_velocity().x(), 0.2, 1e-6);
  EXPECT_NEAR(decoded.body_velocity().y(), -0.04, 1e-6);
  // beyond the trunk's reach over planted feet: clamped
  step.vel_des = {0.0f, 0.0f, 0.0f};
  step.pos_des = {0.5f, -0.5f, 0.0f};
  decoded = decode_user_gait_step(step);
  EXPECT_DOUBLE_EQ(decoded.position_offset_m.x(), UserGaitRanges{}.offset_x.upper);
  EXPECT_DOUBLE_EQ(decoded.position_offset_m.y(), UserGaitRanges{}.offset_y.lower);
}

TEST(UserGaitChecks, AFlightLongerThanThePronksIsRefusedWithItsSections) {
  UserGaitDefinition definition;
  definition.sections = {{{true, true, true, true}, 5},
                         {{false, false, false, false}, max_flight_segments()},
                         {{true, true, true, true}, 5}};
  EXPECT_EQ(definition_problem(definition), "");
  definition.sections[1].duration_units = 3;
  definition.sections.insert(definition.sections.begin() + 2,
                             {{false, false, false, false}, max_flight_segments() - 2});
  EXPECT_EQ(definition_problem(definition),
            "sections 2..3 keep every foot off the ground for " + std::to_string(max_flight_segments() + 1) +
                " units (" + std::to_string(30 * (max_flight_segments() + 1)) + " ms); the robot flies at most " +
                std::to_string(max_flight_segments()) + " units (" + std::to_string(30 * max_flight_segments()) +
                " ms)");
}

TEST(UserGaitChecks, ADefinitionLongerThanTheLimitIsRefused) {
  UserGaitDefinition definition;
  definition.sections = {{{true, true, true, true}, 5000}};
  EXPECT_NE(definition_problem(definition).find("more than 120 s"), std::string::npos);
}

TEST(UserGaitChecks, StepsOutsideTheLegsReachOrNotOfGait110OrWithoutTimeAreRefused) {
  UserGaitParameters parameters;
  parameters.steps = {user_step(), user_step()};
  EXPECT_EQ(parameters_problem(parameters), "");
  parameters.steps[1].ctrl_point[0] = 0.3f;  // RL 0.3 m forward
  EXPECT_EQ(parameters_problem(parameters),
            "step 2: landing point of RL (x 0.300, y 0.000 m) is outside the leg's reach (|x| <= 0.15, |y| <= 0.08 m "
            "from under the hip)");
  parameters.steps[1] = user_step(0);
  EXPECT_EQ(parameters_problem(parameters), "step 2: duration must be > 0 ms, found 0");
  parameters.steps[1] = user_step();
  parameters.steps[0].gait_id = 26;
  EXPECT_EQ(parameters_problem(parameters),
            "step 1: mode and gait_id must be 11 and 110 (a user gait step), found 11 and 26");
}

TEST(UserGaitProgramBuild, TheProgramLastsAsLongAsItsLongerPart) {
  UserGaitDefinition definition;
  definition.sections = {{{true, false, false, true}, 10}, {{true, true, true, true}, 4}};
  UserGaitParameters parameters;
  parameters.steps = {user_step(200), user_step(100)};
  const auto program = build_user_gait_program(definition, parameters);
  EXPECT_NEAR(program->sequence_s(), 14 * 0.03, 1e-12);
  EXPECT_NEAR(program->steps_s(), 0.3, 1e-12);
  EXPECT_NEAR(program->duration_s(), 0.42, 1e-12);
  EXPECT_EQ(program->sequence->segments(), 14);
  EXPECT_FALSE(program->sequence->in_stance(1, 3));
}

}  // namespace
}  // namespace cerebellum
