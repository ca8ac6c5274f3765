#include "io/lcm_highlevel/user_gait_file.hpp"

#include <toml++/toml.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <sstream>

#include "io/lcm_highlevel/toml_shape.hpp"

namespace cerebellum {
namespace {

constexpr std::string_view kDefinitionHeader = "# Gait Def";
constexpr std::string_view kParametersHeader = "# Gait Params";
constexpr long kMaxSectionUnits = 10000;  // 300 s

// the first problem found, with where it is
class Problem {
 public:
  bool found() const { return !text_.empty(); }
  const std::string& text() const { return text_; }
  void set(std::string text) {
    if (text_.empty()) text_ = std::move(text);
  }

 private:
  std::string text_;
};

std::string quoted(std::string_view text) { return std::string(1, '\'').append(text).append(1, '\''); }

std::string where(std::string_view table, std::size_t index, std::string_view key) {
  return std::string(table) + " " + std::to_string(index + 1) + ": " + std::string(key);
}

std::optional<long long> integer_in(const toml::node* node, long long lower, long long upper) {
  if (node == nullptr || !node->is_integer()) return std::nullopt;
  const long long value = node->as_integer()->get();
  if (value < lower || value > upper) return std::nullopt;
  return value;
}

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

void check_keys(const toml::table& table, const std::set<std::string_view>& accepted, std::string_view name,
                std::size_t index, Problem& problem) {
  for (const auto& [key, node] : table) {
    if (accepted.count(key.str()) == 0) {
      std::string list;
      for (std::string_view a : accepted) list += (list.empty() ? "" : ", ") + std::string(a);
      problem.set(where(name, index, key.str()) + " is not a known key (accepted: " + list + ")");
    }
  }
}

// the [[name]] tables of the document, 1..kMaxGaitEntries of them, and nothing else at the top
const toml::array* entries(const toml::table& document, std::string_view name, Problem& problem) {
  for (const auto& [key, node] : document) {
    if (key.str() != name) problem.set(quoted(key.str()) + " is not a [[" + std::string(name) + "]] table");
  }
  const toml::array* array = document[name].as_array();
  if (array == nullptr || array->empty()) {
    problem.set("no [[" + std::string(name) + "]] tables");
    return nullptr;
  }
  if (array->size() > kMaxGaitEntries) {
    problem.set("more than " + std::to_string(kMaxGaitEntries) + " [[" + std::string(name) + "]] tables");
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

UserGaitDefinition read_definition(const toml::table& document, Problem& problem) {
  UserGaitDefinition definition;
  const toml::array* sections = entries(document, "section", problem);
  if (sections == nullptr) return definition;
  for (std::size_t i = 0; i < sections->size(); ++i) {
    const toml::table& table = *sections->get(i)->as_table();
    check_keys(table, {"contact", "duration"}, "section", i, problem);
    GaitSection section;
    const toml::array* contact = table["contact"].as_array();
    if (contact == nullptr || contact->size() != 4) {
      problem.set(where("section", i, "contact") + " must be a list of 4 values 0 or 1 (FR, FL, RR, RL)");
    } else {
      for (std::size_t leg = 0; leg < 4; ++leg) {
        const std::optional<long long> value = integer_in(contact->get(leg), 0, 1);
        if (!value) problem.set(where("section", i, "contact") + " must be a list of 4 values 0 or 1 (FR, FL, RR, RL)");
        section.stance[leg] = value.value_or(1) == 1;
      }
    }
    const std::optional<long long> duration = integer_in(table.get("duration"), 1, kMaxSectionUnits);
    if (!duration) {
      problem.set(where("section", i, "duration") + " must be an integer in [1, " + std::to_string(kMaxSectionUnits) +
                  "] (units of 30 ms)");
    }
    section.duration_units = static_cast<int>(duration.value_or(0));
    definition.sections.push_back(section);
  }
  if (!definition.sections.empty()) definition.sections.back().stance = {true, true, true, true};
  return definition;
}

template <std::size_t N>
void read_floats(const toml::table& table, std::string_view key, std::size_t index, std::array<float, N>& out,
                 Problem& problem) {
  const toml::node* node = table.get(key);
  if (node == nullptr) return;
  const toml::array* array = node->as_array();
  const std::string message = where("step", index, key) + " must be a list of " + std::to_string(N) + " finite numbers";
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
             bool required, Problem& problem) {
  const toml::node* node = table.get(key);
  if (node == nullptr && !required) return 0;
  const std::optional<long long> value = integer_in(node, lower, upper);
  if (!value) {
    problem.set(where("step", index, key) + (node == nullptr ? " is missing; it" : "") + " must be an integer in [" +
                std::to_string(lower) + ", " + std::to_string(upper) + "]");
  }
  return static_cast<int>(value.value_or(0));
}

UserGaitParameters read_parameters(const toml::table& document, Problem& problem) {
  UserGaitParameters parameters;
  const toml::array* steps = entries(document, "step", problem);
  if (steps == nullptr) return parameters;
  constexpr long long kInt8Min = std::numeric_limits<std::int8_t>::min();
  constexpr long long kInt8Max = std::numeric_limits<std::int8_t>::max();
  constexpr long long kInt32Min = std::numeric_limits<std::int32_t>::min();
  constexpr long long kInt32Max = std::numeric_limits<std::int32_t>::max();
  for (std::size_t i = 0; i < steps->size(); ++i) {
    const toml::table& table = *steps->get(i)->as_table();
    check_keys(table,
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
    for (float encoded : step.step_height) {
      // two swing heights in mm packed as a + 1000 * b
      if (encoded < 0.0f || encoded >= 1.0e6f) {
        problem.set(where("step", i, "step_height") + " values must be in [0, 1000000) (h1 mm + 1000 * h2 mm)");
      }
    }
    parameters.steps.push_back(step);
  }
  return parameters;
}

}  // namespace

UserGaitParse parse_user_gait_file(std::string_view text) {
  UserGaitParse result;
  UserGaitFile file;
  if (text.substr(0, kDefinitionHeader.size()) == kDefinitionHeader) {
    file.kind = UserGaitFile::Kind::Definition;
  } else if (text.substr(0, kParametersHeader.size()) == kParametersHeader) {
    file.kind = UserGaitFile::Kind::Parameters;
  } else {
    result.error = "does not begin with '# Gait Def' or '# Gait Params'";
    return result;
  }
  // the parser recurses on dotted keys and nesting: refuse deep shapes before it sees them
  if (std::string shape = toml_shape_problem(text); !shape.empty()) {
    result.error = "refused before parsing: " + shape;
    return result;
  }
  toml::table document;
  try {
    document = toml::parse(text);
  } catch (const toml::parse_error& e) {
    std::ostringstream out;
    out << "not valid TOML at line " << e.source().begin.line << ", column " << e.source().begin.column << ": "
        << e.description();
    result.error = out.str();
    return result;
  }
  Problem problem;
  if (file.kind == UserGaitFile::Kind::Definition) {
    file.definition = read_definition(document, problem);
  } else {
    file.parameters = read_parameters(document, problem);
  }
  if (problem.found()) {
    result.error = problem.text();
    return result;
  }
  result.file = std::move(file);
  return result;
}

}  // namespace cerebellum
