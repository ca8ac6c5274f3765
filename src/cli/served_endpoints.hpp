// What `cerebellum sim` serves, in words for its ready line: each enabled interface with its
// endpoints, so a user sees where to point a client without reading the configuration.
#pragma once

#include <string>

#include "loop/mc_config.hpp"

namespace cerebellum {

// "high-level LCM robot_control_cmd udpm://...; ...": one clause per served endpoint group
std::string served_endpoints(const McConfig& config);

}  // namespace cerebellum
