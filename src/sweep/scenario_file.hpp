// Scenario files (`cerebellum sweep FILE`), read strictly like the MC's configuration: unknown or
// repeated keys, values of the wrong type or out of range, an axis with no values are refused
// with a ConfigError naming the file, the key and what is accepted. The format: docs/sweeps.md.
#pragma once

#include <cstddef>
#include <string>

#include "loop/config_error.hpp"
#include "sweep/scenario.hpp"

namespace cerebellum {

inline constexpr std::size_t kScenarioMaxBytes = 256 * 1024;
inline constexpr std::size_t kScenarioMaxListEntries = 10000;  // commands, pushes, faults, an axis's values
inline constexpr double kScenarioMaxDurationS = 7 * 24 * 3600.0;

// name: the file for messages; base_dir: where a relative robot.config is found
SweepSpec parse_scenario(const std::string& text, const std::string& name, const std::string& base_dir);
SweepSpec load_scenario(const std::string& path);

}  // namespace cerebellum
