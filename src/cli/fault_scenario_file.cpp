#include "cli/fault_scenario_file.hpp"

#include <yaml-cpp/yaml.h>

#include <filesystem>

#include "loop/timed_fault_entry.hpp"
#include "loop/yaml_section.hpp"
#include "core/text_file.hpp"

namespace cerebellum {

namespace {
constexpr const char* kKind = "fault scenario";
}  // namespace

std::vector<TimedFault> parse_fault_scenario(const std::string& text, const std::string& name) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ConfigError(std::string(kKind) + " " + name + ": not valid YAML: " + e.what());
  }
  if (root.IsNull()) return {};
  const SectionReader top(root, name, "<top>", {"faults"}, kKind);
  const YAML::Node list = root["faults"];
  if (!list || list.IsNull()) return {};
  if (!list.IsSequence()) top.fail("faults", "must be a list of entries with at_s, fault and optionally duration_s");
  if (list.size() > kFaultScenarioMaxEntries) {
    top.fail("faults",
             "has " + std::to_string(list.size()) + " entries; at most " + std::to_string(kFaultScenarioMaxEntries));
  }
  std::vector<TimedFault> scenario;
  scenario.reserve(list.size());
  for (std::size_t i = 0; i < list.size(); ++i) {
    std::string entry_name = "faults[";
    entry_name += std::to_string(i);
    entry_name += ']';
    scenario.push_back(read_timed_fault(list[i], name, entry_name, kKind, kFaultScenarioMaxTimeS, kFaultScenarioMaxTimeS));
  }
  return scenario;
}

std::vector<TimedFault> load_fault_scenario(const std::string& path) {
  if (std::filesystem::is_directory(path)) {
    throw ConfigError(std::string(kKind) + " " + path + ": is a folder; give the YAML file");
  }
  std::string error;
  const std::optional<std::string> text = read_text_file(path, kFaultScenarioMaxBytes, error);
  if (!text) throw ConfigError(std::string(kKind) + " " + path + ": " + error);
  return parse_fault_scenario(*text, path);
}

}  // namespace cerebellum
