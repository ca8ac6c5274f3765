// A [[step]] table of robot_control_cmd fields, the format of the seed's sequential-motion files
// (mode, gait_id, contact, value, duration, vel_des, rpy_des, pos_des, acc_des, foot_pose,
// ctrl_point, step_height), read into a HighLevelCommand with the first problem found named by
// table, index, key and what was expected. Uploaded gait parameters and motion files share it.
#pragma once

#include <toml++/toml.h>

#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <string_view>

#include "core/high_level_command.hpp"

namespace cerebellum {

// the first problem found, with where it is
class TomlProblem {
 public:
  bool found() const { return !text_.empty(); }
  const std::string& text() const { return text_; }
  void set(std::string text) {
    if (text_.empty()) text_ = std::move(text);
  }

 private:
  std::string text_;
};

// "step 3: duration" (index counted from 1 in messages)
std::string toml_where(std::string_view table, std::size_t index, std::string_view key);
// an integer node within [lower, upper], or nothing
std::optional<long long> toml_integer_in(const toml::node* node, long long lower, long long upper);
// every key of the table is accepted, else the problem names the first other one
void check_toml_keys(const toml::table& table, const std::set<std::string_view>& accepted, std::string_view name,
                     std::size_t index, TomlProblem& problem);
// the [[name]] tables of the document (1..max_entries, each a table); other top-level keys are
// problems unless listed in other_keys
const toml::array* toml_entries(const toml::table& document, std::string_view name, std::size_t max_entries,
                                const std::set<std::string_view>& other_keys, TomlProblem& problem);

// one [[step]] table (index counted from 0); life_count is accepted and read too
HighLevelCommand read_command_step(const toml::table& table, std::size_t index, TomlProblem& problem);

// "not valid TOML at line L, column C: ..." for a parse error
std::string toml_parse_error_text(const toml::parse_error& error);

// the document of a text, or nothing and why: shapes deep enough to overflow the parser's stack
// are refused before it sees them (core/toml_shape.hpp), then the parser's error with its line
std::optional<toml::table> parse_toml_document(std::string_view text, std::string& error);

}  // namespace cerebellum
