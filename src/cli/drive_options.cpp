#include "cli/drive_options.hpp"

#include <cmath>
#include <stdexcept>

#include "cli/option_number.hpp"
#include "teleop/pad_mapping.hpp"

namespace cerebellum {

std::string drive_usage() {
  return "usage: cerebellum drive [--ttl N]\n"
         "  drives a running MC (cerebellum sim, or a robot) with a gamepad: SDL2's game controllers,\n"
         "  plugged before or after the start; robot_control_cmd at 10 Hz, a new life_count when the\n"
         "  command changes; the robot's mode and gait are printed as they change.\n"
         "  The pad unplugged, Ctrl-C or SIGTERM: the velocity is set to zero and the program ends;\n"
         "  the MC damps 0.5 s after the last heartbeat.\n"
         "  --ttl N       multicast ttl of the LCM urls, 0..255 (default 255; 0 keeps packets on this host)\n" +
         pad_mapping_help();
}

DriveOptions parse_drive_options(const std::vector<std::string>& args) {
  DriveOptions options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--help" || arg == "-h") {
      options.help = true;
      continue;
    }
    if (arg != "--ttl" && arg != "--virtual-pad") {
      throw std::invalid_argument("drive: unknown option '" + arg + "'\n" + drive_usage());
    }
    if (i + 1 >= args.size()) throw std::invalid_argument("drive: " + arg + " needs a value");
    const std::string& value = args[++i];
    if (arg == "--virtual-pad") {
      options.virtual_pad_script = value;
      continue;
    }
    const double ttl = option_number("drive: --ttl", value, "an integer in [0, 255]");
    if (ttl != std::floor(ttl) || ttl < 0 || ttl > 255) {
      throw std::invalid_argument("drive: --ttl must be an integer in [0, 255], got '" + value + "'");
    }
    options.ttl = static_cast<int>(ttl);
  }
  return options;
}

}  // namespace cerebellum
