// The human form of gait parameters converted as the seed's example client converts it (section
// 2.4.3), checked field by field against values worked out by hand.
#include "motions/user_gait_convert.hpp"

#include <gtest/gtest.h>

#include "motions/user_gait_file.hpp"

namespace cerebellum {
namespace {

const char* const kHuman = R"(# Gait Params
[[step]]
type            = "usergait"
body_vel_des    = [0.1, -0.02, 0.3]
body_pos_des    = [0.01, 0.02, 0.03, 0.04, 0.05, 0.24]
landing_pos_des = [0.05, 0.01, 0.0,  -0.05, 0.02, 0.0,  -0.04, 0.03, 0.0,  0.06, -0.01, 0.0]
step_height     = [0.0505, 0.01, 0.02, 0.06]
weight          = [1, 2, 3, 4, 5, 6]
use_mpc_traj    = 1
mu              = 0.4
landing_gain    = 1.5
gait_id         = 110
duration        = 150
)";

TEST(UserGaitConvert, EveryFieldLandsWhereTheSeedsConverterPutsIt) {
  const UserGaitConversion converted = convert_gait_parameters(kHuman);
  ASSERT_EQ(converted.error, "");
  EXPECT_TRUE(is_converted_gait_parameters(converted.text));
  EXPECT_FALSE(is_converted_gait_parameters(kHuman));
  const UserGaitParse parsed = parse_user_gait_file(converted.text);
  ASSERT_TRUE(parsed.file.has_value()) << parsed.error << "\n" << converted.text;
  ASSERT_EQ(parsed.file->parameters.steps.size(), 1u);
  const HighLevelCommand& s = parsed.file->parameters.steps[0];
  EXPECT_EQ(s.mode, 11);
  EXPECT_EQ(s.gait_id, 110);
  EXPECT_EQ(s.duration, 150);
  EXPECT_EQ(s.value, 1);
  EXPECT_EQ(s.contact, 15);  // floor(1.5 * 10)
  EXPECT_FLOAT_EQ(s.vel_des[2], 0.3f);
  EXPECT_FLOAT_EQ(s.rpy_des[1], 0.02f);
  EXPECT_FLOAT_EQ(s.pos_des[2], 0.24f);
  EXPECT_FLOAT_EQ(s.foot_pose[0], 0.05f);   // FR x
  EXPECT_FLOAT_EQ(s.foot_pose[3], 0.02f);   // FL y
  EXPECT_FLOAT_EQ(s.foot_pose[4], -0.04f);  // RR x
  EXPECT_FLOAT_EQ(s.ctrl_point[0], 0.06f);  // RL x
  EXPECT_FLOAT_EQ(s.ctrl_point[1], -0.01f);
  EXPECT_FLOAT_EQ(s.ctrl_point[2], 0.4f);  // mu
  EXPECT_FLOAT_EQ(s.acc_des[5], 6.0f);
  // millimetres rounded up: 50.5 -> 51
  EXPECT_FLOAT_EQ(s.step_height[0], 51.0f + 1000.0f * 10.0f);
  EXPECT_FLOAT_EQ(s.step_height[1], 20.0f + 1000.0f * 60.0f);
}

TEST(UserGaitConvert, AWrongHumanFileNamesTheStepAndKey) {
  std::string text = kHuman;
  text.replace(text.find("landing_pos_des = ["), 19, "landing_pos_des = [1, ");
  EXPECT_EQ(convert_gait_parameters(text).error, "step 1: landing_pos_des must be a list of 12 numbers");
  EXPECT_EQ(convert_gait_parameters("[[step]]\n").error, "does not begin with '# Gait Params'");
  std::string wrong_type = kHuman;
  wrong_type.replace(wrong_type.find("\"usergait\""), 10, "\"walk\"");
  EXPECT_EQ(convert_gait_parameters(wrong_type).error, "step 1: type must be \"usergait\"");
}

}  // namespace
}  // namespace cerebellum
