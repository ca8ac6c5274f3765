// The user gait files a client uploads on user_gait_file: a gait definition ("# Gait Def": the
// contact schedule) or gait parameters ("# Gait Params": one robot_control_cmd per step, already
// converted from the human file by the client). Parsed with toml++ and validated; the error names
// the table, the key and what is accepted.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "control/locomotion/gait_table.hpp"
#include "core/high_level_command.hpp"

namespace cerebellum {

// largest user gait file accepted, in bytes of text (uploaded or read from a folder)
inline constexpr std::size_t kMaxUserGaitFileBytes = 256 * 1024;

// the first line of each kind of file
inline constexpr std::string_view kGaitDefinitionHeader = "# Gait Def";
inline constexpr std::string_view kGaitParametersHeader = "# Gait Params";

inline constexpr double kGaitSectionUnitS = kGaitSegmentS;  // one unit of a section's duration
inline constexpr std::size_t kMaxGaitEntries = 1000;

struct GaitSection {
  std::array<bool, 4> stance{};  // FR, FL, RR, RL: true = on the ground
  int duration_units = 0;        // of kGaitSectionUnitS
};

struct UserGaitDefinition {
  std::vector<GaitSection> sections;  // the last one is forced to full contact
};

struct UserGaitParameters {
  std::vector<HighLevelCommand> steps;
};

struct UserGaitFile {
  enum class Kind { Definition, Parameters };
  Kind kind = Kind::Definition;
  UserGaitDefinition definition;  // when kind == Definition
  UserGaitParameters parameters;  // when kind == Parameters
};

struct UserGaitParse {
  std::optional<UserGaitFile> file;  // set when the text is valid
  std::string error;                 // why not, otherwise
};

UserGaitParse parse_user_gait_file(std::string_view text);

}  // namespace cerebellum
