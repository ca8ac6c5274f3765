#include "cli/log_options.hpp"

#include "cli/option_number.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cerebellum {
namespace {

int parse_port(const std::string& text) {
  const std::string accepted = "one of the interface ports " + lcm_port_list();
  const double value = option_number("--port", text, accepted);
  const auto& ports = interface_ports();
  if (std::find(ports.begin(), ports.end(), value) == ports.end()) {
    throw std::invalid_argument("--port: must be " + accepted + ", got " + text);
  }
  return static_cast<int>(value);
}

// walks the arguments: options with a value through on_option, the one positional through on_positional
template <typename OnOption>
void walk(const std::vector<std::string>& args, const std::string& usage, std::string& positional, OnOption on_option) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw std::invalid_argument(arg + " needs a value\n" + usage);
      return args[++i];
    };
    if (arg.rfind("-", 0) == 0 && arg.size() > 1) {
      if (!on_option(arg, value)) throw std::invalid_argument("unknown option '" + arg + "'\n" + usage);
    } else if (positional.empty()) {
      positional = arg;
    } else {
      throw std::invalid_argument("one file prefix only, got '" + positional + "' and '" + arg + "'\n" + usage);
    }
  }
}

}  // namespace

const std::vector<int>& interface_ports() {
  static const std::vector<int> ports(kLcmPorts.begin(), kLcmPorts.end());
  return ports;
}

std::string log_file_path(const std::string& prefix, int port) {
  return prefix + "." + std::to_string(port) + ".lcmlog";
}

std::string log_usage() {
  return "usage: cerebellum log [PREFIX] [--port P]... [--force]\n"
         "  records every channel of the interface with lcm-logger, one file per LCM port:\n"
         "  PREFIX.<port>.lcmlog, until Ctrl-C. PREFIX default: cerebellum-<date>-<time>\n"
         "  --port P   only this port (repeatable): " +
         lcm_port_list() +
         "\n"
         "  --force    overwrite existing files\n";
}

std::string replay_usage() {
  return "usage: cerebellum replay PREFIX|FILE.<port>.lcmlog [--speed X] [--ttl N] [--port P]...\n"
         "  publishes the events of PREFIX.<port>.lcmlog on their own ports, merged in recorded order\n"
         "  and with the recorded timing\n"
         "  --speed X  playback speed (X > 0, default 1)\n"
         "  --ttl N    multicast ttl (0..255, default 0: this machine only)\n"
         "  --port P   only this port (repeatable): " +
         lcm_port_list() + "\n";
}

LogOptions parse_log_options(const std::vector<std::string>& args) {
  LogOptions options;
  walk(args, log_usage(), options.prefix, [&](const std::string& arg, auto value) {
    if (arg == "--help" || arg == "-h") {
      options.help = true;
    } else if (arg == "--force") {
      options.force = true;
    } else if (arg == "--port") {
      options.ports.push_back(parse_port(value()));
    } else {
      return false;
    }
    return true;
  });
  if (options.ports.empty()) options.ports = interface_ports();
  return options;
}

ReplayOptions parse_replay_options(const std::vector<std::string>& args) {
  ReplayOptions options;
  walk(args, replay_usage(), options.prefix, [&](const std::string& arg, auto value) {
    if (arg == "--help" || arg == "-h") {
      options.help = true;
    } else if (arg == "--speed") {
      const std::string& text = value();
      options.speed = option_number(arg, text, "a number > 0");
      if (options.speed <= 0.0) throw std::invalid_argument("--speed: must be > 0, got " + text);
    } else if (arg == "--ttl") {
      const std::string& text = value();
      const double ttl = option_number(arg, text, "an integer in [0, 255]");
      if (ttl < 0 || ttl > 255 || ttl != std::floor(ttl)) {
        throw std::invalid_argument("--ttl: must be an integer in [0, 255], got " + text);
      }
      options.ttl = static_cast<int>(ttl);
    } else if (arg == "--port") {
      options.ports.push_back(parse_port(value()));
    } else {
      return false;
    }
    return true;
  });
  if (!options.help && options.prefix.empty()) {
    throw std::invalid_argument("needs the log's PREFIX (or one PREFIX.<port>.lcmlog file)\n" + replay_usage());
  }
  if (options.ports.empty()) options.ports = interface_ports();
  return options;
}

std::vector<std::string> logger_command(const std::string& prefix, int port, bool force) {
  // lcm-logger flushes when an event arrives more than the interval after the last flush: with
  // 1 ms (the least it takes) the file on disk follows the traffic and can be read while recording
  std::vector<std::string> command = {"lcm-logger", "--quiet", "--flush-interval=1", "--lcm-url=" + lcm_url(port, 0)};
  if (force) command.push_back("--force");
  command.push_back(log_file_path(prefix, port));
  return command;
}

}  // namespace cerebellum
