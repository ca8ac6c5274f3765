#include "motions/user_gait_file.hpp"

#include <gtest/gtest.h>

#include <string>

namespace cerebellum {
namespace {

constexpr const char* kMoonwalkDefinition =
    "# Gait Def\n"
    "[[section]]\ncontact = [1, 1, 1, 1]\nduration = 10\n\n"
    "[[section]]\ncontact  = [0, 0, 0, 0]\nduration = 3\n\n"
    "[[section]]\ncontact = [0, 1, 1, 0]\nduration = 4\n\n"
    "[[section]]\ncontact = [1, 0, 0, 1]\nduration = 5\n";

// as the example client writes it: "# Gait Params" and toml.dumps of the converted steps
constexpr const char* kConvertedParameters =
    "# Gait Params\n"
    "[[step]]\n"
    "mode = 11\ngait_id = 110\ncontact = 15\nlife_count = 0\n"
    "vel_des = [0.1, 0.0, 0.0]\nrpy_des = [0.0, 0.0, 0.0]\npos_des = [0.0, 0.0, 0.0]\n"
    "acc_des = [0.0, 0.0, 100.0, 0.0, 0.0, 0.0]\nctrl_point = [0.02, 0.0, 0.4]\n"
    "foot_pose = [0.05, 0.0, 0.0, 0.0, 0.0, 0.0]\nstep_height = [60010.0, 10060.0]\n"
    "value = 1\nduration = 300\n"
    "[[step]]\n"
    "mode = 11\ngait_id = 110\nduration = 240\nvel_des = [0, 0, 0]\n";

std::string error_of(const std::string& text) {
  const UserGaitParse parsed = parse_user_gait_file(text);
  EXPECT_FALSE(parsed.file.has_value()) << text;
  return parsed.error;
}

TEST(UserGaitFile, DefinitionSectionsInOrderWithTheLastForcedToFullContact) {
  const UserGaitParse parsed = parse_user_gait_file(kMoonwalkDefinition);
  ASSERT_TRUE(parsed.file.has_value()) << parsed.error;
  ASSERT_EQ(parsed.file->kind, UserGaitFile::Kind::Definition);
  const auto& sections = parsed.file->definition.sections;
  ASSERT_EQ(sections.size(), 4u);
  EXPECT_EQ(sections[0].stance, (std::array<bool, 4>{true, true, true, true}));
  EXPECT_EQ(sections[1].stance, (std::array<bool, 4>{false, false, false, false}));
  EXPECT_EQ(sections[2].stance, (std::array<bool, 4>{false, true, true, false}));
  EXPECT_EQ(sections[3].stance, (std::array<bool, 4>{true, true, true, true}));  // was 1, 0, 0, 1
  EXPECT_EQ(sections[0].duration_units, 10);
  EXPECT_EQ(sections[2].duration_units, 4);
  EXPECT_EQ(sections[3].duration_units, 5);
}

TEST(UserGaitFile, ConvertedParametersBecomeCommands) {
  const UserGaitParse parsed = parse_user_gait_file(kConvertedParameters);
  ASSERT_TRUE(parsed.file.has_value()) << parsed.error;
  ASSERT_EQ(parsed.file->kind, UserGaitFile::Kind::Parameters);
  const auto& steps = parsed.file->parameters.steps;
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_EQ(steps[0].mode, 11);
  EXPECT_EQ(steps[0].gait_id, 110);
  EXPECT_EQ(steps[0].contact, 15);
  EXPECT_EQ(steps[0].value, 1);
  EXPECT_EQ(steps[0].duration, 300);
  EXPECT_FLOAT_EQ(steps[0].vel_des[0], 0.1f);
  EXPECT_FLOAT_EQ(steps[0].acc_des[2], 100.0f);
  EXPECT_FLOAT_EQ(steps[0].ctrl_point[2], 0.4f);
  EXPECT_FLOAT_EQ(steps[0].foot_pose[0], 0.05f);
  EXPECT_FLOAT_EQ(steps[0].step_height[0], 60010.0f);
  EXPECT_FLOAT_EQ(steps[0].step_height[1], 10060.0f);
  // integers are accepted where floats are expected; absent fields are zero
  EXPECT_EQ(steps[1].duration, 240);
  EXPECT_EQ(steps[1].contact, 0);
  EXPECT_EQ(steps[1].vel_des, (std::array<float, 3>{0, 0, 0}));
}

TEST(UserGaitFile, NeedsOneOfTheTwoHeaders) {
  EXPECT_NE(error_of("[[section]]\ncontact = [1, 1, 1, 1]\nduration = 1\n").find("'# Gait Def' or '# Gait Params'"),
            std::string::npos);
  EXPECT_NE(error_of("\n# Gait Def\n").find("does not begin with"), std::string::npos);
  EXPECT_NE(error_of("").find("does not begin with"), std::string::npos);
}

TEST(UserGaitFile, TomlSyntaxErrorsNameTheLine) {
  const std::string error = error_of("# Gait Def\n[[section]]\ncontact = [1, 1, 1, 1\nduration = 1\n");
  EXPECT_NE(error.find("not valid TOML at line"), std::string::npos) << error;
}

TEST(UserGaitFile, DefinitionErrorsNameTheSectionAndKey) {
  const std::string head = "# Gait Def\n[[section]]\ncontact = [1, 1, 1, 1]\nduration = 2\n[[section]]\n";
  EXPECT_NE(error_of(head + "contact = [1, 1, 1]\nduration = 2\n").find("section 2: contact must be a list of 4"),
            std::string::npos);
  EXPECT_NE(error_of(head + "contact = [1, 2, 1, 1]\nduration = 2\n").find("section 2: contact"), std::string::npos);
  EXPECT_NE(error_of(head + "contact = [1, 1, 1, 1]\nduration = 0\n").find("section 2: duration must be an integer"),
            std::string::npos);
  EXPECT_NE(error_of(head + "contact = [1, 1, 1, 1]\nduration = 1.5\n").find("section 2: duration"), std::string::npos);
  EXPECT_NE(error_of(head + "contact = [1, 1, 1, 1]\n").find("section 2: duration"), std::string::npos);
  EXPECT_NE(error_of(head + "contact = [1, 1, 1, 1]\nduration = 2\nheight = 3\n")
                .find("section 2: height is not a known key"),
            std::string::npos);
  EXPECT_NE(error_of("# Gait Def\n").find("no [[section]] tables"), std::string::npos);
  EXPECT_NE(error_of("# Gait Def\nname = 'x'\n[[section]]\ncontact = [1, 1, 1, 1]\nduration = 2\n")
                .find("'name' is not a [[section]] table"),
            std::string::npos);
}

TEST(UserGaitFile, ParameterErrorsNameTheStepAndKey) {
  const std::string head = "# Gait Params\n[[step]]\nmode = 11\ngait_id = 110\nduration = 100\n[[step]]\n";
  EXPECT_NE(error_of(head + "gait_id = 110\nduration = 100\n").find("step 2: mode is missing"), std::string::npos);
  EXPECT_NE(error_of(head + "mode = 300\ngait_id = 110\nduration = 100\n")
                .find("step 2: mode must be an integer in [-128, 127]"),
            std::string::npos);
  EXPECT_NE(error_of(head + "mode = 11\ngait_id = 110\nduration = -5\n").find("step 2: duration"), std::string::npos);
  EXPECT_NE(error_of(head + "mode = 11\ngait_id = 110\nduration = 100\nvel_des = [0.1, 0.0]\n")
                .find("step 2: vel_des must be a list of 3 finite numbers"),
            std::string::npos);
  EXPECT_NE(
      error_of(head + "mode = 11\ngait_id = 110\nduration = 100\nrpy_des = [nan, 0.0, 0.0]\n").find("step 2: rpy_des"),
      std::string::npos);
  EXPECT_NE(error_of(head + "mode = 11\ngait_id = 110\nduration = 100\nstep_height = [-1.0, 0.0]\n")
                .find("step 2: step_height values must be in [0, 1000000)"),
            std::string::npos);
  // the human file, not converted by the client
  EXPECT_NE(error_of("# Gait Params\n[[step]]\ntype = \"usergait\"\nbody_vel_des = [0.1, 0.0, 0.0]\ngait_id = 110\n"
                     "duration = 100\n")
                .find("step 1: body_vel_des is not a known key"),
            std::string::npos);
}

// a text of ~80 kB with a dotted key 40,000 parts deep overflowed the parser's stack (SIGSEGV on
// the adapter thread): it is refused before the parser sees it
TEST(UserGaitFile, AKeyFortyThousandPartsDeepIsRefusedWithoutParsing) {
  std::string key = "a";
  for (int i = 1; i < 40000; ++i) key += ".a";
  const std::string error = error_of("# Gait Def\n" + key + ".b = 1\n");
  EXPECT_NE(error.find("refused before parsing: line 2: a dotted key with more than"), std::string::npos) << error;
  std::string nested(40000, '[');
  const std::string nesting_error = error_of("# Gait Params\nx = " + nested + "\n");
  EXPECT_NE(nesting_error.find("nested more than"), std::string::npos) << nesting_error;
}

}  // namespace
}  // namespace cerebellum
