// Motion files: a valid file becomes the motion it describes; every malformed one is refused with
// what is wrong, where, and what was expected.
#include "motions/motion_file.hpp"

#include <gtest/gtest.h>

#include <string>

namespace cerebellum {
namespace {

const char* const kShake = R"(# a comment
id = 81
name = "wave"

[[step]]
mode = 21
gait_id = 2
contact = 0b1110
foot_pose = [0.12, -0.02, 0.14, 0.0, 0.0, 0.0]
duration = 2000

[[step]]
mode = 21
gait_id = 0
rpy_des = [0.0, 0.2, -0.1]
pos_des = [0.01, 0, -0.02]
ctrl_point = [0.2, 0.0, 0.0]
duration = 700
)";

// the error of a text with one line of the valid file replaced
std::string error_with(const std::string& from, const std::string& to) {
  std::string text = kShake;
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  const MotionFileParse parse = parse_motion_file(text);
  EXPECT_FALSE(parse.motion.has_value()) << to;
  return parse.error;
}

TEST(MotionFile, AValidFileBecomesItsIdNameAndSteps) {
  const MotionFileParse parse = parse_motion_file(kShake);
  ASSERT_TRUE(parse.motion.has_value()) << parse.error;
  const Motion& motion = *parse.motion;
  EXPECT_EQ(motion.id, 81);
  EXPECT_EQ(motion.name, "wave");
  ASSERT_EQ(motion.steps.size(), 2u);
  EXPECT_EQ(motion.steps[0].mode, 21);
  EXPECT_EQ(motion.steps[0].gait_id, 2);
  EXPECT_EQ(motion.steps[0].contact, 14);
  EXPECT_FLOAT_EQ(motion.steps[0].foot_pose[1], -0.02f);
  EXPECT_EQ(motion.steps[0].duration, 2000);
  EXPECT_FLOAT_EQ(motion.steps[1].rpy_des[1], 0.2f);
  EXPECT_FLOAT_EQ(motion.steps[1].pos_des[1], 0.0f);  // an integer where a float is expected is taken
  EXPECT_FLOAT_EQ(motion.steps[1].ctrl_point[0], 0.2f);
  EXPECT_DOUBLE_EQ(motion.duration_s(), 2.7);
}

TEST(MotionFile, BrokenTomlIsRefusedWithItsLineAndColumn) {
  const std::string error = error_with("duration = 700", "duration = = 700");
  EXPECT_NE(error.find("not valid TOML at line 18"), std::string::npos) << error;
}

TEST(MotionFile, EachWrongFieldIsNamedWithItsStepAndWhatIsExpected) {
  EXPECT_NE(error_with("id = 81", "id = 0").find("id must be an integer in [1, 100]"), std::string::npos);
  EXPECT_NE(error_with("id = 81", "id = 101").find("id must be an integer in [1, 100]"), std::string::npos);
  EXPECT_NE(error_with("id = 81", "").find("id must be"), std::string::npos);
  EXPECT_NE(error_with("name = \"wave\"", "name = 3").find("name must be a text"), std::string::npos);
  EXPECT_NE(error_with("duration = 700", "duration = 0").find("step 2: duration must be in [1, 60000] ms, found 0"),
            std::string::npos);
  EXPECT_NE(error_with("duration = 700", "duration = -5").find("step 2: duration must be an integer"),
            std::string::npos);
  EXPECT_NE(error_with("duration = 2000", "").find("step 1: duration is missing"), std::string::npos);
  EXPECT_NE(error_with("rpy_des = [0.0, 0.2, -0.1]", "rpy_des = [0.0, 0.2]")
                .find("step 2: rpy_des must be a list of 3 finite numbers"),
            std::string::npos);
  EXPECT_NE(error_with("rpy_des = [0.0, 0.2, -0.1]", "rpy_des = [0.0, nan, 0.1]").find("step 2: rpy_des"),
            std::string::npos);
  EXPECT_NE(error_with("rpy_des = [0.0, 0.2, -0.1]", "rpy_des = [0.0, inf, 0.1]").find("step 2: rpy_des"),
            std::string::npos);
  EXPECT_NE(error_with("rpy_des = [0.0, 0.2, -0.1]", "rpy_des = [0.0, \"up\", 0.1]").find("step 2: rpy_des"),
            std::string::npos);
  EXPECT_NE(error_with("gait_id = 0", "gait = 0").find("step 2: gait is not a known key"), std::string::npos);
  EXPECT_NE(error_with("name = \"wave\"", "name = \"wave\"\nspeed = 2").find("'speed' is not a [[step]] table"),
            std::string::npos);
}

TEST(MotionFile, AMotionMayNameItsOwnUserGaitFiles) {
  const std::string head = "id = 82\nname = \"g\"\n";
  const std::string step = "[[step]]\nmode = 11\ngait_id = 110\nduration = 900\n";
  const MotionFileParse ok =
      parse_motion_file(head + "user_gait = { definition = \"d.toml\", parameters = \"p.toml\" }\n" + step);
  ASSERT_TRUE(ok.motion.has_value()) << ok.error;
  EXPECT_EQ(ok.motion->user_gait_definition, "d.toml");
  EXPECT_EQ(ok.motion->user_gait_parameters, "p.toml");
  for (const char* wrong : {"user_gait = \"d.toml\"\n", "user_gait = { definition = \"d.toml\" }\n",
                            "user_gait = { definition = \"d.toml\", parameters = 3 }\n"}) {
    EXPECT_EQ(parse_motion_file(head + wrong + step).error,
              "user_gait must be { definition = \"FILE\", parameters = \"FILE\" }")
        << wrong;
  }
}

TEST(MotionFile, AFileWithoutStepsIsRefused) {
  EXPECT_EQ(parse_motion_file("id = 80\nname = \"nothing\"\n").error, "no [[step]] tables");
}

TEST(MotionFile, TooManyStepsOrTooManyBytesOrTooDeepAShapeAreRefusedBeforeTheyCostAnything) {
  std::string many = "id = 80\nname = \"long\"\n";
  for (std::size_t i = 0; i <= kMaxMotionSteps; ++i) many += "[[step]]\nmode = 21\ngait_id = 3\nduration = 10\n";
  EXPECT_EQ(parse_motion_file(many).error, "more than 200 [[step]] tables");
  const std::string huge(kMaxMotionFileBytes + 1, '#');
  EXPECT_NE(parse_motion_file(huge).error.find("more than the limit of 65536"), std::string::npos);
  std::string deep = "id = 80\nname = \"deep\"\nx = ";
  deep += std::string(100, '[') + std::string(100, ']');
  EXPECT_NE(parse_motion_file(deep).error.find("refused before parsing"), std::string::npos);
}

}  // namespace
}  // namespace cerebellum
