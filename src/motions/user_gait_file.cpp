#include "motions/user_gait_file.hpp"

#include <toml++/toml.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <sstream>

#include "motions/command_step_toml.hpp"

namespace cerebellum {
namespace {

constexpr long kMaxSectionUnits = 10000;  // 300 s

UserGaitDefinition read_definition(const toml::table& document, TomlProblem& problem) {
  UserGaitDefinition definition;
  const toml::array* sections = toml_entries(document, "section", kMaxGaitEntries, {}, problem);
  if (sections == nullptr) return definition;
  for (std::size_t i = 0; i < sections->size(); ++i) {
    const toml::table& table = *sections->get(i)->as_table();
    check_toml_keys(table, {"contact", "duration"}, "section", i, problem);
    GaitSection section;
    const toml::array* contact = table["contact"].as_array();
    if (contact == nullptr || contact->size() != 4) {
      problem.set(toml_where("section", i, "contact") + " must be a list of 4 values 0 or 1 (FR, FL, RR, RL)");
    } else {
      for (std::size_t leg = 0; leg < 4; ++leg) {
        const std::optional<long long> value = toml_integer_in(contact->get(leg), 0, 1);
        if (!value)
          problem.set(toml_where("section", i, "contact") + " must be a list of 4 values 0 or 1 (FR, FL, RR, RL)");
        section.stance[leg] = value.value_or(1) == 1;
      }
    }
    const std::optional<long long> duration = toml_integer_in(table.get("duration"), 1, kMaxSectionUnits);
    if (!duration) {
      problem.set(toml_where("section", i, "duration") + " must be an integer in [1, " +
                  std::to_string(kMaxSectionUnits) + "] (units of 30 ms)");
    }
    section.duration_units = static_cast<int>(duration.value_or(0));
    definition.sections.push_back(section);
  }
  if (!definition.sections.empty()) definition.sections.back().stance = {true, true, true, true};
  return definition;
}

UserGaitParameters read_parameters(const toml::table& document, TomlProblem& problem) {
  UserGaitParameters parameters;
  const toml::array* steps = toml_entries(document, "step", kMaxGaitEntries, {}, problem);
  if (steps == nullptr) return parameters;
  for (std::size_t i = 0; i < steps->size(); ++i) {
    const HighLevelCommand step = read_command_step(*steps->get(i)->as_table(), i, problem);
    for (float encoded : step.step_height) {
      // two swing heights in mm packed as a + 1000 * b
      if (encoded < 0.0f || encoded >= 1.0e6f) {
        problem.set(toml_where("step", i, "step_height") + " values must be in [0, 1000000) (h1 mm + 1000 * h2 mm)");
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
  if (text.substr(0, kGaitDefinitionHeader.size()) == kGaitDefinitionHeader) {
    file.kind = UserGaitFile::Kind::Definition;
  } else if (text.substr(0, kGaitParametersHeader.size()) == kGaitParametersHeader) {
    file.kind = UserGaitFile::Kind::Parameters;
  } else {
    result.error = "does not begin with '# Gait Def' or '# Gait Params'";
    return result;
  }
  const std::optional<toml::table> parsed = parse_toml_document(text, result.error);
  if (!parsed) return result;
  const toml::table& document = *parsed;
  TomlProblem problem;
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
