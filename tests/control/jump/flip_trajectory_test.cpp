// The flip file: written and read back alike, and every malformed file refused with its line and
// reason, before a flip starts.
#include <gtest/gtest.h>

#include <string>

#include "control/jump/flip_trajectory.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

FlipTrajectory two_rows() {
  FlipTrajectory t;
  t.samples.push_back({0.0, 0, {0.0, 0.26, 0.0}, {0.79, -1.22, 0.79, -1.22}, {0, 0, 0, 0}, {1.0, -2.0, 3.0, -4.0}});
  t.samples.push_back({0.02, 1, {0.01, 0.27, -0.1}, {0.8, -1.2, 0.9, -1.1}, {1.5, 2.5, -3.5, 4.5}, {5.0, 6.0, -7.0, 11.9}});
  return t;
}

std::string parse_error(const std::string& text) {
  std::string error;
  EXPECT_FALSE(parse_flip_trajectory(text, robot::kTorqueMaxNm, error).has_value());
  return error;
}

std::string header_and(const std::string& rows) { return flip_trajectory_header() + "\n" + rows; }

TEST(FlipTrajectory, WhatIsWrittenIsReadBack) {
  const std::string text = flip_trajectory_text(two_rows(), {"a comment", "another"});
  std::string error;
  const auto read = parse_flip_trajectory(text, robot::kTorqueMaxNm, error);
  ASSERT_TRUE(read.has_value()) << error;
  ASSERT_EQ(read->samples.size(), 2u);
  EXPECT_EQ(read->samples[1].phase, 1);
  EXPECT_DOUBLE_EQ(read->samples[1].time_s, 0.02);
  EXPECT_DOUBLE_EQ(read->samples[1].trunk[2], -0.1);
  EXPECT_DOUBLE_EQ(read->samples[1].q_rad[3], -1.1);
  EXPECT_DOUBLE_EQ(read->samples[1].qd_rad_s[2], -3.5);
  EXPECT_DOUBLE_EQ(read->samples[1].tau_nm[3], 11.9);
}

TEST(FlipTrajectory, AMalformedFileIsRefusedWithItsLineAndReason) {
  EXPECT_EQ(parse_error("time_s,phase\n0,0\n"), "line 1: the header is not \"" + flip_trajectory_header() + "\"");
  EXPECT_EQ(parse_error(header_and("0,0,0,0.26,0\n")), "line 2: 5 columns, the header has 17");
  EXPECT_EQ(parse_error(header_and("0,0,0,0.26,0,0.79,-1.22,0.79,-1.22,0,0,0,0,1,2,nan,4\n")),
            "line 2: column 16 (\"nan\") is not a finite number");
  EXPECT_EQ(parse_error(header_and("0,3,0,0.26,0,0.79,-1.22,0.79,-1.22,0,0,0,0,1,2,3,4\n")), "line 2: phase 3 is not 0, 1 or 2");
  EXPECT_EQ(parse_error("# only a comment\n"), "no header line");
  EXPECT_EQ(parse_error(header_and("0,0,0,0.26,0,0.79,-1.22,0.79,-1.22,0,0,0,0,1,2,3,4\n")), "fewer than two rows");
  EXPECT_EQ(parse_error(header_and("0.1,0,0,0.26,0,0.79,-1.22,0.79,-1.22,0,0,0,0,1,2,3,4\n")),
            "line 2: the first row's time is 0.1 s, not 0");
  EXPECT_EQ(parse_error(header_and("0,1,0,0.26,0,0.79,-1.22,0.79,-1.22,0,0,0,0,1,2,3,4\n"
                                   "0,1,0,0.26,0,0.79,-1.22,0.79,-1.22,0,0,0,0,1,2,3,4\n")),
            "line 3: time 0 s does not increase");
  EXPECT_EQ(parse_error(header_and("0,1,0,0.26,0,0.79,-1.22,0.79,-1.22,0,0,0,0,1,2,3,4\n"
                                   "0.1,0,0,0.26,0,0.79,-1.22,0.79,-1.22,0,0,0,0,1,2,3,4\n")),
            "line 3: phase 0 goes back");
}

TEST(FlipTrajectory, AJointOutOfRangeOrATorqueBeyondTheMotorsIsRefused) {
  EXPECT_EQ(parse_error(header_and("0,0,0,0.26,0,0.79,-0.2,0.79,-1.22,0,0,0,0,1,2,3,4\n")),
            "line 2: front_knee at -0.2 rad, outside its range -2.53..-0.52");
  EXPECT_EQ(parse_error(header_and("0,0,0,0.26,0,0.79,-1.22,0.79,-1.22,0,0,0,0,1,2,3,12.5\n")),
            "line 2: rear_knee torque 12.5 Nm beyond the motors' 12 Nm");
}

TEST(FlipTrajectory, TheShippedBackFlipIsAValidFile) {
  std::string error;
  const auto read = read_flip_trajectory(std::string(CEREBELLUM_SOURCE_DIR) + "/config/flips/back_flip.csv",
                                         robot::kTorqueMaxNm, error);
  ASSERT_TRUE(read.has_value()) << error;
  // a full back turn, landed within the 0.5 m of the take-off
  EXPECT_NEAR(read->samples.back().trunk[2] - read->samples.front().trunk[2], -2.0 * robot::kPi, 1e-6);
  EXPECT_LE(std::abs(read->samples.back().trunk[0] - read->samples.front().trunk[0]), 0.5);
  EXPECT_EQ(read->samples.back().phase, 2);
}

TEST(FlipTrajectory, TheShippedFrontFlipIsAValidFileThatTouchesDownOverItsTakeOff) {
  std::string error;
  const auto read = read_flip_trajectory(std::string(CEREBELLUM_SOURCE_DIR) + "/config/flips/front_flip.csv",
                                         robot::kTorqueMaxNm, error);
  ASSERT_TRUE(read.has_value()) << error;
  // a full turn nose down (the SDK's positive pitch); planned to touch down over the take-off, since
  // the body runs ahead of the plan by about 0.3 m (docs/jumps.md)
  EXPECT_NEAR(read->samples.back().trunk[2] - read->samples.front().trunk[2], 2.0 * robot::kPi, 1e-6);
  EXPECT_LE(std::abs(read->samples.back().trunk[0] - read->samples.front().trunk[0]), 1e-6);
  EXPECT_EQ(read->samples.back().phase, 2);
}

}  // namespace
}  // namespace cerebellum
