// Command-line options of `cerebellum log` and `cerebellum replay`, and the names they derive:
// one log file per LCM port of the CyberDog2 interface (docs/lcm-types.md).
#pragma once

#include <string>
#include <vector>

#include "io/lcm_common/lcm_network.hpp"

namespace cerebellum {

// the interface's ports (io/lcm_common/lcm_network.hpp)
const std::vector<int>& interface_ports();
// <prefix>.<port>.lcmlog
std::string log_file_path(const std::string& prefix, int port);

struct LogOptions {
  std::string prefix;      // empty: cerebellum-<local date>-<time>
  std::vector<int> ports;  // default: every interface port
  bool force = false;      // overwrite existing files
  bool help = false;
};

struct ReplayOptions {
  std::string prefix;      // or one file <prefix>.<port>.lcmlog
  std::vector<int> ports;  // default: every interface port with a file
  double speed = 1.0;
  int ttl = 0;  // 0: this machine only
  bool help = false;
};

// throw std::invalid_argument naming the option and the accepted values
LogOptions parse_log_options(const std::vector<std::string>& args);
ReplayOptions parse_replay_options(const std::vector<std::string>& args);
std::string log_usage();
std::string replay_usage();

// lcm-logger's arguments for one port (argv[0] included)
std::vector<std::string> logger_command(const std::string& prefix, int port, bool force);

}  // namespace cerebellum
