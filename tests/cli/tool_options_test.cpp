// Options of the tools: sim --viewer/--record/--telemetry, log and replay.
#include <gtest/gtest.h>

#include <stdexcept>

#include "cli/log_options.hpp"
#include "cli/sim_options.hpp"

namespace cerebellum {
namespace {

// the message of the invalid_argument the parser throws, or "" when it does not throw
template <typename Parse>
std::string error_of(Parse parse, const std::vector<std::string>& args) {
  try {
    parse(args);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

std::string sim_error(const std::vector<std::string>& args) { return error_of(parse_sim_options, args); }

TEST(SimToolOptions, DefaultsAndValues) {
  const SimOptions defaults = parse_sim_options({});
  EXPECT_FALSE(defaults.viewer);
  EXPECT_TRUE(defaults.record_path.empty());
  EXPECT_EQ(defaults.record_fps, 30.0);
  EXPECT_EQ(defaults.record_width, 1280);
  EXPECT_EQ(defaults.record_height, 720);
  EXPECT_EQ(defaults.telemetry_rate_hz, 100.0);

  const SimOptions o = parse_sim_options({"--record", "run.mp4", "--record-fps", "24", "--record-size", "320x240",
                                          "--telemetry", "t.csv", "--telemetry-rate", "50"});
  EXPECT_EQ(o.record_path, "run.mp4");
  EXPECT_EQ(o.record_fps, 24.0);
  EXPECT_EQ(o.record_width, 320);
  EXPECT_EQ(o.record_height, 240);
  EXPECT_EQ(o.telemetry_path, "t.csv");
  EXPECT_EQ(o.telemetry_rate_hz, 50.0);

  EXPECT_TRUE(defaults.progress_path.empty()) << "the bar goes to the output";
  EXPECT_EQ(parse_sim_options({"--record", "run.mp4", "--progress-to", "/dev/tty"}).progress_path, "/dev/tty");

  const SimOptions v = parse_sim_options({"--viewer", "--viewer-screenshot", "shot.png"});
  EXPECT_TRUE(v.viewer);
  EXPECT_EQ(v.viewer_screenshot_path, "shot.png");
}

TEST(SimToolOptions, BadValuesNameTheOptionAndTheAcceptedRange) {
  EXPECT_NE(sim_error({"--record", "a.mp4", "--record-size", "321x240"}).find("--record-size: must be WxH with even"),
            std::string::npos);
  EXPECT_NE(sim_error({"--record", "a.mp4", "--record-size", "640"}).find("--record-size: '640' is not WxH"),
            std::string::npos);
  EXPECT_NE(sim_error({"--record", "a.mp4", "--record-size", "8x8"}).find("16x16 to 3840x2160"), std::string::npos);
  EXPECT_NE(sim_error({"--record", "a.mp4", "--record-fps", "0"}).find("--record-fps: must be in (0, 240]"),
            std::string::npos);
  EXPECT_NE(sim_error({"--telemetry", "t.csv", "--telemetry-rate", "-1"}).find("--telemetry-rate: must be > 0 Hz"),
            std::string::npos);
  EXPECT_NE(sim_error({"--viewer", "--viewer-screenshot", "shot.jpg"}).find("must end in .png"), std::string::npos);
}

TEST(SimToolOptions, OptionsThatNeedAnotherOrExcludeOne) {
  EXPECT_NE(sim_error({"--viewer", "--record", "a.mp4"}).find("--viewer and --record cannot run together"),
            std::string::npos);
  EXPECT_NE(sim_error({"--record-fps", "10"}).find("--record-fps needs --record FILE.mp4"), std::string::npos);
  EXPECT_NE(sim_error({"--record-size", "320x240"}).find("--record-size needs --record"), std::string::npos);
  EXPECT_NE(sim_error({"--viewer-screenshot", "a.png"}).find("--viewer-screenshot needs --viewer"), std::string::npos);
  EXPECT_NE(sim_error({"--progress-to", "/dev/tty"}).find("--progress-to needs --record FILE.mp4"), std::string::npos);
  EXPECT_NE(sim_error({"--telemetry-rate", "10"}).find("--telemetry-rate needs --telemetry"), std::string::npos);
  EXPECT_EQ(sim_error({"--viewer", "--telemetry", "t.csv"}), "");
  EXPECT_EQ(sim_error({"--record", "a.mp4", "--telemetry", "t.csv"}), "");
}

TEST(LogToolOptions, UrlsAndFileNamesPerPort) {
  EXPECT_EQ(interface_ports(), (std::vector<int>{7667, 7669, 7670, 7671}));
  EXPECT_EQ(lcm_url(7670, 0), "udpm://239.255.76.67:7670?ttl=0");
  EXPECT_EQ(log_file_path("runs/a", 7669), "runs/a.7669.lcmlog");
  EXPECT_EQ(logger_command("runs/a", 7671, false),
            (std::vector<std::string>{"lcm-logger", "--quiet", "--flush-interval=1",
                                      "--lcm-url=udpm://239.255.76.67:7671?ttl=0", "runs/a.7671.lcmlog"}));
  EXPECT_EQ(logger_command("b", 7667, true).at(4), "--force");
}

TEST(LogToolOptions, LogParsesPrefixPortsAndForce) {
  const LogOptions defaults = parse_log_options({});
  EXPECT_TRUE(defaults.prefix.empty());
  EXPECT_EQ(defaults.ports, interface_ports());
  const LogOptions o = parse_log_options({"runs/walk", "--port", "7670", "--port", "7671", "--force"});
  EXPECT_EQ(o.prefix, "runs/walk");
  EXPECT_EQ(o.ports, (std::vector<int>{7670, 7671}));
  EXPECT_TRUE(o.force);
  EXPECT_NE(error_of(parse_log_options, {"--port", "1234"})
                .find("--port: must be one of the interface ports 7667, "
                      "7669, 7670, 7671, got 1234"),
            std::string::npos);
  EXPECT_NE(error_of(parse_log_options, {"a", "b"}).find("one file prefix only"), std::string::npos);
  EXPECT_NE(error_of(parse_log_options, {"--ttl", "1"}).find("unknown option '--ttl'"), std::string::npos);
}

TEST(LogToolOptions, ReplayNeedsAPrefixAndChecksSpeedAndTtl) {
  const ReplayOptions o = parse_replay_options({"runs/walk", "--speed", "2", "--ttl", "1"});
  EXPECT_EQ(o.prefix, "runs/walk");
  EXPECT_EQ(o.speed, 2.0);
  EXPECT_EQ(o.ttl, 1);
  EXPECT_EQ(o.ports, interface_ports());
  EXPECT_NE(error_of(parse_replay_options, {}).find("needs the log's PREFIX"), std::string::npos);
  EXPECT_NE(error_of(parse_replay_options, {"a", "--speed", "0"}).find("--speed: must be > 0"), std::string::npos);
  EXPECT_NE(error_of(parse_replay_options, {"a", "--ttl", "256"}).find("--ttl: must be an integer in [0, 255]"),
            std::string::npos);
  EXPECT_NE(error_of(parse_replay_options, {"a", "--ttl"}).find("--ttl needs a value"), std::string::npos);
  EXPECT_TRUE(parse_replay_options({"--help"}).help);
}

}  // namespace
}  // namespace cerebellum
