#include "motions/command_step_toml.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

#include "core/toml_shape.hpp"

namespace cerebellum {
namespace {

std::string quoted(std::string_view text) { return std::string(1, '\'').append(text).append(1, '\''); }

std::optional<double> finite_number(const toml::node& node) {
  double value = 0.0;
  if (node.is_integer()) {
    value = static_cast<double>(node.as_integer()->get());
  } else if (node.is_floating_point()) {
    value = node.as_floating_point()->get();
  } else {
    return std::nullopt;
  }
  if (!std::isfinite(value)) return std::nullopt;
  return value;
}

template <std::size_t N>
void read_floats(const toml::table& table, std::string_view key, std::size_t index, std::array<float, N>& out,
                 TomlProblem& problem) {
  const toml::node* node = table.get(key);
  if (node == nullptr) return;
  const toml::array* array = node->as_array();
  const std::string message =
      toml_where("step", index, key) + " must be a list of " + std::to_string(N) + " finite numbers";
  if (array == nullptr || array->size() != N) {
    problem.set(message);
    return;
  }
  for (std::size_t k = 0; k < N; ++k) {
    const std::optional<double> value = finite_number(*array->get(k));
    if (!value || std::abs(*value) > std::numeric_limits<float>::max()) {
      problem.set(message);
      return;
    }
    out[k] = static_cast<float>(*value);
  }
}

int read_int(const toml::table& table, std::string_view key, std::size_t index, long long lower, long long upper,
             bool required, TomlProblem& problem) {
  const toml::node* node = table.get(key);
  if (node == nullptr && !required) return 0;
  const std::optional<long long> value = toml_integer_in(node, lower, upper);
  if (!value) {
    problem.set(toml_where("step", index, key) + (node == nullptr ? " is missing; it" : "") +
                " must be an integer in [" + std::to_string(lower) + ", " + std::to_string(upper) + "]");
  }
  return static_cast<int>(value.value_or(0));
}

}  // namespace

std::string toml_where(std::string_view table, std::size_t index, std::string_view key) {
  return std::string(table) + " " + std::to_string(index + 1) + ": " + std::string(key);
}

std::optional<long long> toml_integer_in(const toml::node* node, long long lower, long long upper) {
  if (node == nullptr || !node->is_integer()) return std::nullopt;
  const long long value = node->as_integer()->get();
  if (value < lower || value > upper) return std::nullopt;
  return value;
}

void check_toml_keys(const toml::table& table, const std::set<std::string_view>& accepted, std::string_view name,
                     std::size_t index, TomlProblem& problem) {
  for (const auto& [key, node] : table) {
    if (accepted.count(key.str()) == 0) {
      std::string list;
      for (std::string_view a : accepted) list += (list.empty() ? "" : ", ") + std::string(a);
      problem.set(toml_where(name, index, key.str()) + " is not a known key (accepted: " + list + ")");
    }
  }
}

const toml::array* toml_entries(const toml::table& document, std::string_view name, std::size_t max_entries,
                                const std::set<std::string_view>& other_keys, TomlProblem& problem) {
  for (const auto& [key, node] : document) {
    if (key.str() != name && other_keys.count(key.str()) == 0) {
      problem.set(quoted(key.str()) + " is not a [[" + std::string(name) + "]] table");
    }
  }
  const toml::array* array = document[name].as_array();
  if (array == nullptr || array->empty()) {
    problem.set("no [[" + std::string(name) + "]] tables");
    return nullptr;
  }
  if (array->size() > max_entries) {
    problem.set("more than " + std::to_string(max_entries) + " [[" + std::string(name) + "]] tables");
    return nullptr;
  }
  for (const toml::node& entry : *array) {
    if (!entry.is_table()) {
      problem.set(quoted(name) + " must be a list of [[" + std::string(name) + "]] tables");
      return nullptr;
    }
  }
  return array;
}

HighLevelCommand read_command_step(const toml::table& table, std::size_t i, TomlProblem& problem) {
  constexpr long long kInt8Min = std::numeric_limits<std::int8_t>::min();
  constexpr long long kInt8Max = std::numeric_limits<std::int8_t>::max();
  constexpr long long kInt32Min = std::numeric_limits<std::int32_t>::min();
  constexpr long long kInt32Max = std::numeric_limits<std::int32_t>::max();
  check_toml_keys(table,
                  {"mode", "gait_id", "contact", "life_count", "vel_des", "rpy_des", "pos_des", "acc_des", "ctrl_point",
                   "foot_pose", "step_height", "value", "duration"},
                  "step", i, problem);
  HighLevelCommand step;
  step.mode = read_int(table, "mode", i, kInt8Min, kInt8Max, true, problem);
  step.gait_id = read_int(table, "gait_id", i, kInt8Min, kInt8Max, true, problem);
  step.duration = read_int(table, "duration", i, 0, kInt32Max, true, problem);
  step.contact = read_int(table, "contact", i, kInt8Min, kInt8Max, false, problem);
  step.life_count = read_int(table, "life_count", i, kInt8Min, kInt8Max, false, problem);
  step.value = read_int(table, "value", i, kInt32Min, kInt32Max, false, problem);
  read_floats(table, "vel_des", i, step.vel_des, problem);
  read_floats(table, "rpy_des", i, step.rpy_des, problem);
  read_floats(table, "pos_des", i, step.pos_des, problem);
  read_floats(table, "acc_des", i, step.acc_des, problem);
  read_floats(table, "ctrl_point", i, step.ctrl_point, problem);
  read_floats(table, "foot_pose", i, step.foot_pose, problem);
  read_floats(table, "step_height", i, step.step_height, problem);
  return step;
}

std::string toml_parse_error_text(const toml::parse_error& error) {
  std::ostringstream out;
  out << "not valid TOML at line " << error.source().begin.line << ", column " << error.source().begin.column << ": "
      << error.description();
  return out.str();
}

std::optional<toml::table> parse_toml_document(std::string_view text, std::string& error) {
  if (std::string shape = toml_shape_problem(text); !shape.empty()) {
    error = "refused before parsing: " + shape;
    return std::nullopt;
  }
  try {
    return toml::parse(text);
  } catch (const toml::parse_error& e) {
    error = toml_parse_error_text(e);
    return std::nullopt;
  }
}

}  // namespace cerebellum
