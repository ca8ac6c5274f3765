// Command-line options of `cerebellum cmd <verb>` and `cerebellum status`: each verb becomes one
// robot_control_cmd; values outside the interface's ranges are errors naming the option and range.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <cerebellum/highlevel_client.hpp>

#include "io/lcm_common/lcm_network.hpp"
#include "robot_control_cmd_lcmt.hpp"

namespace cerebellum {

struct CmdOptions {
  bool help = false;
  std::string verb;                  // stand, lie, damp, pose, height, walk, raw
  robot_control_cmd_lcmt command{};  // life_count is set by the client
  double timeout_s = 10.0;           // for the mode to be reached
  std::optional<double> hold_s;      // heartbeat after that; empty: until Ctrl-C
  int ttl = 255;                     // of the LCM urls
};

struct StatusOptions {
  bool help = false;
  std::optional<long> count;  // lines to print; empty: until Ctrl-C
  double rate_hz = 5.0;
  double timeout_s = 3.0;  // for the first response
  int ttl = 255;
  bool diagnostics = false;  // also the MC's own figures (mc_diagnostics), once a second
};

std::string cmd_usage();
std::string status_usage();
// throw std::invalid_argument with a message naming the option and what it accepts
CmdOptions parse_cmd_options(const std::vector<std::string>& args);
StatusOptions parse_status_options(const std::vector<std::string>& args);

// the interface's ports (io/lcm_common/lcm_network.hpp): commands and user gait files, responses,
// odometry
inline constexpr int kCommandPort = kLcmCommandPort;
inline constexpr int kResponsePort = kLcmResponsePort;
inline constexpr int kOdometryPort = kLcmMotorSdkPort;
// the interface's url on one port with the given ttl
inline std::string highlevel_url(int port, int ttl) { return lcm_url(port, ttl); }
// a high-level client's three urls with the given ttl (cmd, status, drive)
inline HighLevelClientOptions highlevel_client_options(int ttl) {
  HighLevelClientOptions options;
  options.command_url = highlevel_url(kCommandPort, ttl);
  options.response_url = highlevel_url(kResponsePort, ttl);
  options.odometry_url = highlevel_url(kOdometryPort, ttl);
  return options;
}

}  // namespace cerebellum
