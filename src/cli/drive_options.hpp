// Command-line options of `cerebellum drive` (a gamepad client of the high-level interface).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace cerebellum {

struct DriveOptions {
  bool help = false;
  int ttl = 255;  // of the LCM urls
  // a script played into a virtual pad instead of waiting for a real one (tests; docs/driving.md)
  std::optional<std::string> virtual_pad_script;
};

std::string drive_usage();
// throws std::invalid_argument with a message naming the option and what it accepts
DriveOptions parse_drive_options(const std::vector<std::string>& args);

}  // namespace cerebellum
