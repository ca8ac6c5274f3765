#include "cli/cmd_options.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace cerebellum {
namespace {

std::string cmd_error(const std::vector<std::string>& args) {
  try {
    parse_cmd_options(args);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

std::string status_error(const std::vector<std::string>& args) {
  try {
    parse_status_options(args);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(CmdOptions, StandLieAndDampAreTheirModeAndGait) {
  const CmdOptions stand = parse_cmd_options({"stand"});
  EXPECT_EQ(stand.command.mode, 12);
  EXPECT_EQ(stand.command.gait_id, 0);
  EXPECT_EQ(stand.command.duration, 0);
  EXPECT_FALSE(stand.hold_s.has_value());  // until Ctrl-C
  EXPECT_DOUBLE_EQ(stand.timeout_s, 10.0);
  EXPECT_EQ(stand.ttl, 255);
  const CmdOptions lie = parse_cmd_options({"lie"});
  EXPECT_EQ(lie.command.mode, 7);
  EXPECT_EQ(lie.command.gait_id, 1);
  EXPECT_EQ(lie.hold_s.value(), 0.0);
  const CmdOptions damp = parse_cmd_options({"damp", "--hold", "2.5", "--ttl", "0", "--timeout", "3"});
  EXPECT_EQ(damp.command.mode, 7);
  EXPECT_EQ(damp.command.gait_id, 0);
  EXPECT_EQ(damp.hold_s.value(), 2.5);
  EXPECT_EQ(damp.ttl, 0);
  EXPECT_DOUBLE_EQ(damp.timeout_s, 3.0);
}

TEST(CmdOptions, PoseIsQpStandWithAbsoluteRollPitchAndHeight) {
  const CmdOptions pose = parse_cmd_options(
      {"pose", "--roll", "0.1", "--pitch", "-0.2", "--yaw", "0.3", "--height", "0.3", "--duration", "1.5"});
  EXPECT_EQ(pose.command.mode, 3);
  EXPECT_EQ(pose.command.gait_id, 0);
  EXPECT_FLOAT_EQ(pose.command.rpy_des[0], 0.1f);
  EXPECT_FLOAT_EQ(pose.command.rpy_des[1], -0.2f);
  EXPECT_FLOAT_EQ(pose.command.rpy_des[2], 0.3f);
  EXPECT_FLOAT_EQ(pose.command.pos_des[2], 0.3f);
  EXPECT_EQ(pose.command.duration, 1500);
  EXPECT_FLOAT_EQ(parse_cmd_options({"pose"}).command.pos_des[2], 0.235f);
}

TEST(CmdOptions, HeightIsAbsoluteHeightPoseControlWithADuration) {
  const CmdOptions height = parse_cmd_options({"height", "0.22"});
  EXPECT_EQ(height.command.mode, 21);
  EXPECT_EQ(height.command.gait_id, 5);
  EXPECT_FLOAT_EQ(height.command.pos_des[2], 0.22f);
  EXPECT_EQ(height.command.duration, 1000);
  EXPECT_EQ(parse_cmd_options({"height", "0.15", "--duration", "0.4"}).command.duration, 400);
}

TEST(CmdOptions, WalkDefaultsToSlowTrotAndTakesTheGaitsLimits) {
  const CmdOptions walk = parse_cmd_options({"walk", "--vx", "0.3", "--yaw-rate", "-0.5"});
  EXPECT_EQ(walk.command.mode, 11);
  EXPECT_EQ(walk.command.gait_id, 27);
  EXPECT_FLOAT_EQ(walk.command.vel_des[0], 0.3f);
  EXPECT_FLOAT_EQ(walk.command.vel_des[1], 0.0f);
  EXPECT_FLOAT_EQ(walk.command.vel_des[2], -0.5f);
  EXPECT_FLOAT_EQ(walk.command.step_height[0], 0.05f);
  EXPECT_FLOAT_EQ(walk.command.step_height[1], 0.05f);
  EXPECT_EQ(walk.command.duration, 0);
  // the flying trot goes faster forward than backward; the gait may come after the velocity
  const CmdOptions fast = parse_cmd_options({"walk", "--vx", "1.6", "--gait", "10", "--duration", "3"});
  EXPECT_EQ(fast.command.gait_id, 10);
  EXPECT_FLOAT_EQ(fast.command.vel_des[0], 1.6f);
  EXPECT_EQ(fast.command.duration, 3000);
  EXPECT_EQ(cmd_error({"walk", "--vx", "-1.6", "--gait", "10"}),
            "cmd walk: --vx must be a number in [-1.2, 1.6] m/s (gait 10), got '-1.6'");
  EXPECT_EQ(cmd_error({"walk", "--vx", "0.7"}),
            "cmd walk: --vx must be a number in [-0.6, 0.6] m/s (gait 27), got '0.7'");
  EXPECT_EQ(cmd_error({"walk", "--vy", "0.2", "--gait", "2", "--yaw-rate", "0.6"}),
            "cmd walk: --vy must be a number in [-0.15, 0.15] m/s (gait 2), got '0.2'");
  EXPECT_EQ(cmd_error({"walk", "--gait", "5"}), "cmd walk: --gait must be one of 2, 3, 4, 7, 10, 26, 27, got 5");
  EXPECT_EQ(cmd_error({"walk", "--step-height", "0.08"}),
            "cmd walk: --step-height must be a number in [0.005, 0.06] m, got '0.08'");
}

TEST(CmdOptions, RawSetsEveryField) {
  const CmdOptions raw = parse_cmd_options({"raw",
                                            "--mode",
                                            "62",
                                            "--gait",
                                            "3",
                                            "--contact",
                                            "14",
                                            "--value",
                                            "2",
                                            "--duration",
                                            "1.3",
                                            "--vel",
                                            "0.1,0.2,0.3",
                                            "--rpy",
                                            "0,0.1,0",
                                            "--pos",
                                            "0,0,0.2",
                                            "--acc",
                                            "1,2,3,4,5,6",
                                            "--ctrl-point",
                                            "0.01,0,0",
                                            "--foot-pose",
                                            "0,0,0.05,0,0,0",
                                            "--step-height",
                                            "0.04,0.05"});
  const robot_control_cmd_lcmt& c = raw.command;
  EXPECT_EQ(c.mode, 62);
  EXPECT_EQ(c.gait_id, 3);
  EXPECT_EQ(c.contact, 14);
  EXPECT_EQ(c.value, 2);
  EXPECT_EQ(c.duration, 1300);
  EXPECT_FLOAT_EQ(c.vel_des[2], 0.3f);
  EXPECT_FLOAT_EQ(c.rpy_des[1], 0.1f);
  EXPECT_FLOAT_EQ(c.pos_des[2], 0.2f);
  EXPECT_FLOAT_EQ(c.acc_des[5], 6.0f);
  EXPECT_FLOAT_EQ(c.ctrl_point[0], 0.01f);
  EXPECT_FLOAT_EQ(c.foot_pose[2], 0.05f);
  EXPECT_FLOAT_EQ(c.step_height[1], 0.05f);
  EXPECT_EQ(parse_cmd_options({"raw", "--mode", "-1"}).command.mode, -1);
  EXPECT_EQ(parse_cmd_options({"raw", "--mode", "3"}).command.contact, 0x0F);
}

TEST(CmdOptions, ErrorsNameTheOptionAndTheRange) {
  EXPECT_EQ(cmd_error({"pose", "--roll", "0.6"}), "cmd pose: --roll must be a number in [-0.52, 0.52] rad, got '0.6'");
  EXPECT_EQ(cmd_error({"pose", "--pitch", "-0.3"}),
            "cmd pose: --pitch must be a number in [-0.25, 0.3] rad, got '-0.3'");
  EXPECT_EQ(cmd_error({"pose", "--height", "abc"}), "cmd pose: --height must be a number in [0.15, 0.32] m, got 'abc'");
  EXPECT_EQ(cmd_error({"height", "0.3"}), "cmd height: H must be a number in [0.15, 0.27] m, got '0.3'");
  EXPECT_EQ(cmd_error({"height"}), "cmd height: needs the height H in m, e.g. 'cmd height 0.22'");
  EXPECT_EQ(cmd_error({"height", "0.2", "--duration", "0"}),
            "cmd height: --duration must be a number in [0.001, 2147483] s, got '0'");
  EXPECT_EQ(cmd_error({"raw", "--gait", "1"}), "cmd raw: --mode is required (an integer in [-128, 127])");
  EXPECT_EQ(cmd_error({"raw", "--mode", "200"}), "cmd raw: --mode must be an integer in [-128, 127], got '200'");
  EXPECT_EQ(cmd_error({"raw", "--mode", "1.5"}), "cmd raw: --mode must be an integer in [-128, 127], got '1.5'");
  EXPECT_EQ(cmd_error({"raw", "--mode", "7", "--vel", "1,2"}),
            "cmd raw: --vel must be 3 comma-separated numbers in [-1e6, 1e6], got '1,2'");
  EXPECT_EQ(cmd_error({"raw", "--mode", "7", "--rpy", "1,2,nan"}),
            "cmd raw: --rpy must be 3 comma-separated numbers in [-1e6, 1e6], got '1,2,nan'");
  EXPECT_EQ(cmd_error({"stand", "--vx", "1"}), "cmd stand: unknown option '--vx' (accepted: --hold, --timeout, --ttl)");
  EXPECT_EQ(cmd_error({"stand", "now"}), "cmd stand: unknown argument 'now' (accepted: --hold, --timeout, --ttl)");
  EXPECT_EQ(cmd_error({"stand", "--hold"}), "cmd stand: --hold needs a value");
  EXPECT_EQ(cmd_error({"stand", "--ttl", "256"}), "cmd stand: --ttl must be an integer in [0, 255], got '256'");
  EXPECT_EQ(cmd_error({"stand", "--timeout", "0"}), "cmd stand: --timeout must be a number in [0.1, 3600] s, got '0'");
  EXPECT_EQ(cmd_error({"stand", "--hold", "-1"}), "cmd stand: --hold must be a number in [0, 1000000] s, got '-1'");
  EXPECT_EQ(
      cmd_error({"fly"}).rfind("cmd: unknown verb 'fly' (accepted: damp, height, lie, pose, raw, stand, walk)", 0), 0u);
  EXPECT_EQ(cmd_error({}).rfind("cmd: missing verb", 0), 0u);
}

TEST(CmdOptions, HelpAnywhere) {
  EXPECT_TRUE(parse_cmd_options({"--help"}).help);
  EXPECT_TRUE(parse_cmd_options({"walk", "-h"}).help);
  EXPECT_TRUE(parse_status_options({"--help"}).help);
}

TEST(StatusOptions, CountRateTimeoutTtl) {
  const StatusOptions defaults = parse_status_options({});
  EXPECT_FALSE(defaults.count.has_value());
  EXPECT_DOUBLE_EQ(defaults.rate_hz, 5.0);
  EXPECT_DOUBLE_EQ(defaults.timeout_s, 3.0);
  const StatusOptions options = parse_status_options({"--count", "3", "--rate", "20", "--timeout", "1", "--ttl", "0"});
  EXPECT_EQ(options.count.value(), 3);
  EXPECT_DOUBLE_EQ(options.rate_hz, 20.0);
  EXPECT_DOUBLE_EQ(options.timeout_s, 1.0);
  EXPECT_EQ(options.ttl, 0);
  EXPECT_EQ(status_error({"--count", "0"}), "status: --count must be an integer in [1, 1000000000], got '0'");
  EXPECT_EQ(status_error({"--rate", "100"}), "status: --rate must be a number in [0.1, 50] Hz, got '100'");
  EXPECT_EQ(status_error({"--speed", "1"}),
            "status: unknown option '--speed' (accepted: --count, --diagnostics, --rate, --timeout, --ttl)");
  EXPECT_FALSE(defaults.diagnostics);
  EXPECT_TRUE(parse_status_options({"--diagnostics", "--count", "2"}).diagnostics) << "a flag: it takes no value";
  EXPECT_EQ(parse_status_options({"--diagnostics", "--count", "2"}).count.value(), 2);
}

TEST(HighLevelUrl, InterfaceGroupWithPortAndTtl) {
  EXPECT_EQ(highlevel_url(7671, 255), "udpm://239.255.76.67:7671?ttl=255");
  EXPECT_EQ(highlevel_url(7667, 0), "udpm://239.255.76.67:7667?ttl=0");
}

}  // namespace
}  // namespace cerebellum
