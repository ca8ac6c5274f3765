#include "sweep/scenario_file.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "control/locomotion/gait_table.hpp"
#include "core/high_level_command.hpp"
#include "core/text_file.hpp"
#include "loop/timed_fault_entry.hpp"
#include "loop/yaml_section.hpp"
#include "modes/jump_mode.hpp"

namespace cerebellum {

namespace {

constexpr const char* kKind = "scenario";
constexpr double kMaxImpulseNs = 1000.0;
constexpr double kMaxSpeedMs = 10.0;

std::string indexed(const std::string& list, std::size_t i) { return list + "[" + std::to_string(i) + "]"; }

// a list of numbers within [lower, upper]; empty lists are refused, since an axis or a gait set
// with no values would make a sweep of nothing
std::vector<double> number_list(const SectionReader& section, const YAML::Node& node, const std::string& section_name,
                                const std::string& list_key, double lower, double upper, bool integers) {
  const YAML::Node list = node[list_key];
  const std::string key = section_name + "." + list_key;
  if (!list.IsSequence()) section.fail(key, "must be a list of numbers, e.g. [1, 2, 3]");
  if (list.size() == 0) section.fail(key, "has no values; give at least one");
  if (list.size() > kScenarioMaxListEntries)
    section.fail(key, "has " + std::to_string(list.size()) + " values; at most " +
                          std::to_string(kScenarioMaxListEntries));
  std::vector<double> values;
  for (std::size_t i = 0; i < list.size(); ++i) {
    double v = 0.0;
    const std::string where = indexed(key, i);
    if (!list[i].IsScalar() || !YAML::convert<double>::decode(list[i], v) || !std::isfinite(v))
      section.fail(where, "must be a number, got '" + (list[i].IsScalar() ? list[i].Scalar() : "<not a scalar>") + "'");
    if (v < lower || v > upper)
      section.fail(where, "must be in [" + std::to_string(lower) + ", " + std::to_string(upper) + "], got " +
                              list[i].Scalar());
    if (integers && v != std::floor(v)) section.fail(where, "must be a whole number, got " + list[i].Scalar());
    values.push_back(v);
  }
  return values;
}

// a list of entries, not empty, not larger than the limit
void check_list(const SectionReader& top, const YAML::Node& list, const std::string& key, const std::string& what) {
  if (!list.IsSequence() || list.size() == 0) top.fail(key, what);
  if (list.size() > kScenarioMaxListEntries)
    top.fail(key, "has " + std::to_string(list.size()) + " entries; at most " + std::to_string(kScenarioMaxListEntries));
}

bool known_mode(int mode) {
  return std::any_of(kAllModes.begin(), kAllModes.end(), [&](const ModeInfo& m) { return static_cast<int>(m.id) == mode; });
}

bool is_jump(const ScriptedCommand& c) { return c.mode == static_cast<int>(ModeId::Jump3d); }
bool is_motion(const ScriptedCommand& c) { return c.mode == static_cast<int>(ModeId::Motion); }

// a jump of the table or a flip (a flip whose file the MC did not load is refused there with its
// reason: a run may test that)
bool known_jump_id(int id) { return find_jump(id) != nullptr || id == kBackFlipGaitId || id == kFrontFlipGaitId; }

std::string jump_ids() {
  std::string out;
  for (int id = 0; id < 256; ++id)
    if (known_jump_id(id)) out += (out.empty() ? "" : ", ") + std::to_string(id);
  return out;
}

std::string mode_list() {
  std::string out;
  for (const ModeInfo& m : kAllModes) out += (out.empty() ? "" : ", ") + std::to_string(static_cast<int>(m.id));
  return out;
}

// [low, high] within [lower, upper], low <= high
void read_range(const SectionReader& section, const YAML::Node& node, const std::string& section_name,
                const std::string& key, double lower, double upper, double& low, double& high) {
  if (!node[key]) return;
  const std::vector<double> pair = number_list(section, node, section_name, key, lower, upper, false);
  if (pair.size() != 2) section.fail(section_name + "." + key, "must be a range [low, high], e.g. [0.4, 1.2]");
  if (pair[1] < pair[0]) section.fail(section_name + "." + key, "has its high end below its low end");
  low = pair[0];
  high = pair[1];
}

ModelErrorRanges read_model_error(const YAML::Node& node, const std::string& name, bool sensor_noise) {
  const std::string section = "robot.model_error";
  const SectionReader error(node, name, section,
                            {"mass_fraction", "com_offset_m", "foot_friction", "motor_strength_fraction",
                             "actuation_delay_ms", "sensor_noise_scale"},
                            kKind);
  ModelErrorRanges ranges;
  error.number("mass_fraction", ranges.mass_fraction, 0.0, 0.5);
  error.number("com_offset_m", ranges.com_offset_m, 0.0, 0.05);
  read_range(error, node, section, "foot_friction", 0.05, 2.0, ranges.friction_min, ranges.friction_max);
  error.number("motor_strength_fraction", ranges.motor_strength_fraction, 0.0, 0.5);
  double delay_min_ms = 0.0, delay_max_ms = 0.0;
  read_range(error, node, section, "actuation_delay_ms", 0.0, 1e3 * kMaxActuationDelayS, delay_min_ms, delay_max_ms);
  ranges.actuation_delay_min_s = 1e-3 * delay_min_ms;
  ranges.actuation_delay_max_s = 1e-3 * delay_max_ms;
  error.number("sensor_noise_scale", ranges.sensor_noise_scale, 0.0, 10.0);
  if (ranges.sensor_noise_scale != 1.0 && !sensor_noise)
    error.fail(section + ".sensor_noise_scale", "scales the sensor noise: it needs robot.sensor_noise: true");
  return ranges;
}

void read_robot(const YAML::Node& node, const std::string& name, const std::string& base_dir, Scenario& s) {
  const SectionReader robot(node, name, "robot", {"config", "sensor_noise", "model_error"}, kKind);
  robot.path("config", s.config_path);
  if (!s.config_path.empty() && std::filesystem::path(s.config_path).is_relative() && !base_dir.empty())
    s.config_path = (std::filesystem::path(base_dir) / s.config_path).lexically_normal().string();
  robot.flag("sensor_noise", s.sensor_noise);
  if (robot.has("model_error")) s.model_error = read_model_error(node["model_error"], name, s.sensor_noise);
}

// the terrain spec of `cerebellum sim --terrain`; a terrain file is found beside the scenario file
TerrainSpec read_terrain(const SectionReader& top, const std::string& base_dir) {
  std::string text;
  top.text("terrain", text);
  TerrainSpec terrain;
  try {
    terrain = parse_terrain_spec(text);
  } catch (const std::invalid_argument& e) {
    top.fail("terrain", e.what());
  }
  if (terrain.kind == TerrainKind::File && std::filesystem::path(terrain.file).is_relative() && !base_dir.empty())
    terrain.file = (std::filesystem::path(base_dir) / terrain.file).lexically_normal().string();
  return terrain;
}

std::vector<ScriptedCommand> read_commands(const SectionReader& top, const YAML::Node& list, const std::string& name,
                                           double duration_s) {
  check_list(top, list, "commands", "must be a list of commands with at_s, mode and optionally gait, vx_m_s, vy_m_s, yaw_rate_rad_s");
  std::vector<ScriptedCommand> commands;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string where = indexed("commands", i);
    const SectionReader entry(list[i], name, where, {"at_s", "mode", "gait", "vx_m_s", "vy_m_s", "yaw_rate_rad_s"}, kKind);
    if (!entry.has("at_s")) entry.fail(where, "needs at_s (robot seconds from the start)");
    if (!entry.has("mode")) entry.fail(where, "needs mode (a high-level mode id: " + mode_list() + ")");
    ScriptedCommand c;
    entry.number("at_s", c.at_s, 0.0, duration_s);
    double mode = 0.0, gait = 0.0;
    entry.number("mode", mode, 0.0, 255.0);
    if (!known_mode(static_cast<int>(mode)) || mode != std::floor(mode))
      entry.fail(where + ".mode", "must be one of the modes " + mode_list() + "; got " + std::to_string(mode));
    entry.number("gait", gait, 0.0, 255.0);
    if (gait != std::floor(gait)) entry.fail(where + ".gait", "must be a whole number");
    c.mode = static_cast<int>(mode);
    c.gait = static_cast<int>(gait);
    if (c.mode == static_cast<int>(ModeId::Locomotion) && find_gait(c.gait) == nullptr)
      entry.fail(where + ".gait", "is not a gait of the gait table (control/locomotion/gait_table.hpp)");
    if (is_jump(c) && !known_jump_id(c.gait))
      entry.fail(where + ".gait", "is not a jump id of mode 16 (" + jump_ids() + ")");
    entry.number("vx_m_s", c.vx_m_s, -kMaxSpeedMs, kMaxSpeedMs);
    entry.number("vy_m_s", c.vy_m_s, -kMaxSpeedMs, kMaxSpeedMs);
    entry.number("yaw_rate_rad_s", c.yaw_rate_rad_s, -kMaxSpeedMs, kMaxSpeedMs);
    if (!commands.empty() && c.at_s < commands.back().at_s)
      entry.fail(where + ".at_s", "is earlier than the command before it; list the commands in time order");
    commands.push_back(c);
  }
  return commands;
}

SoakSpec read_soak(const YAML::Node& node, const std::string& name) {
  const SectionReader soak(node, name, "soak",
                           {"start_s", "gaits", "hold_min_s", "hold_max_s", "fault_chance", "fault_min_s", "fault_max_s"}, kKind);
  SoakSpec spec;
  if (soak.has("gaits")) {
    spec.gaits.clear();
    for (double g : number_list(soak, node, "soak", "gaits", 0, 255, true)) {
      const GaitSpec* gait = find_gait(static_cast<int>(g));
      if (gait == nullptr) soak.fail("soak.gaits", "names " + std::to_string(static_cast<int>(g)) + ", not a gait of the gait table");
      spec.gaits.push_back(static_cast<int>(g));
    }
  }
  soak.number("start_s", spec.start_s, 0.0, kScenarioMaxDurationS);
  soak.number("hold_min_s", spec.hold_min_s, 0.01, 3600.0);
  soak.number("hold_max_s", spec.hold_max_s, 0.01, 3600.0);
  if (spec.hold_max_s < spec.hold_min_s) soak.fail("soak.hold_max_s", "is below hold_min_s");
  soak.number("fault_chance", spec.fault_chance, 0.0, 1.0);
  soak.number("fault_min_s", spec.fault_min_s, 0.001, 3600.0);
  soak.number("fault_max_s", spec.fault_max_s, 0.001, 3600.0);
  if (spec.fault_max_s < spec.fault_min_s) soak.fail("soak.fault_max_s", "is below fault_min_s");
  return spec;
}

std::vector<ScenarioPush> read_pushes(const SectionReader& top, const YAML::Node& list, const std::string& name,
                                      double duration_s) {
  check_list(top, list, "pushes", "must be a list of pushes with at_s, impulse_n_s and optionally direction_deg, length_s");
  std::vector<ScenarioPush> pushes;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string where = indexed("pushes", i);
    const SectionReader entry(list[i], name, where, {"at_s", "impulse_n_s", "direction_deg", "length_s"}, kKind);
    if (!entry.has("at_s")) entry.fail(where, "needs at_s (robot seconds from the start)");
    if (!entry.has("impulse_n_s")) entry.fail(where, "needs impulse_n_s (the shove's impulse, N s)");
    ScenarioPush p;
    entry.number("at_s", p.at_s, 0.0, duration_s);
    entry.number("impulse_n_s", p.impulse_n_s, 0.0, kMaxImpulseNs);
    entry.number("direction_deg", p.direction_deg, -360.0, 360.0);
    entry.number("length_s", p.length_s, 0.002, 10.0);
    pushes.push_back(p);
  }
  return pushes;
}

std::vector<TimedFault> read_faults(const SectionReader& top, const YAML::Node& list, const std::string& name,
                                    double duration_s) {
  check_list(top, list, "faults", "must be a list of entries with at_s, fault and optionally duration_s");
  std::vector<TimedFault> faults;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string where = indexed("faults", i);
    faults.push_back(read_timed_fault(list[i], name, where, kKind, duration_s, kScenarioMaxDurationS));
  }
  return faults;
}

// the terrain axis: a list of terrain specs, each read as the scenario's own terrain: is
void read_terrain_axis(const SectionReader& sweep, const YAML::Node& node, const std::string& base_dir, Axis& axis) {
  const YAML::Node list = node[axis.name];
  const std::string key = "sweep." + axis.name;
  if (!list.IsSequence()) sweep.fail(key, "must be a list of terrain specs, e.g. [flat, slope:10, step:0.04]");
  if (list.size() == 0) sweep.fail(key, "has no values; give at least one");
  if (list.size() > kScenarioMaxListEntries)
    sweep.fail(key, "has " + std::to_string(list.size()) + " values; at most " + std::to_string(kScenarioMaxListEntries));
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string where = indexed(key, i);
    if (!list[i].IsScalar()) sweep.fail(where, "must be a terrain spec (a string)");
    // the results are CSV with the spec in a column
    if (list[i].Scalar().find(',') != std::string::npos) sweep.fail(where, "may not hold a comma (the results are CSV)");
    TerrainSpec terrain;
    try {
      terrain = parse_terrain_spec(list[i].Scalar());
    } catch (const std::invalid_argument& e) {
      sweep.fail(where, e.what());
    }
    if (terrain.kind == TerrainKind::File && std::filesystem::path(terrain.file).is_relative() && !base_dir.empty())
      terrain.file = (std::filesystem::path(base_dir) / terrain.file).lexically_normal().string();
    axis.values.push_back(static_cast<double>(i));
    axis.terrains.push_back(terrain);
  }
}

std::vector<Axis> read_axes(const YAML::Node& node, const std::string& name, const std::string& base_dir,
                            const Scenario& s) {
  const std::set<std::string> accepted(axis_names().begin(), axis_names().end());
  const SectionReader sweep(node, name, "sweep", accepted, kKind);
  std::vector<Axis> axes;
  // the file's order, so the grid's order is the one the author wrote
  for (const auto& entry : node) {
    Axis axis;
    axis.name = entry.first.Scalar();
    const auto at = std::find(axis_names().begin(), axis_names().end(), axis.name);
    axis.kind = static_cast<AxisKind>(at - axis_names().begin());
    switch (axis.kind) {
      case AxisKind::Seed: axis.values = number_list(sweep, node, "sweep", axis.name, 0, 4294967295.0, true); break;
      case AxisKind::Gait:
        axis.values = number_list(sweep, node, "sweep", axis.name, 0, 255, true);
        for (double g : axis.values)
          if (find_gait(static_cast<int>(g)) == nullptr)
            sweep.fail("sweep.gait", "names " + std::to_string(static_cast<int>(g)) + ", not a gait of the gait table");
        if (std::none_of(s.commands.begin(), s.commands.end(),
                         [](const ScriptedCommand& c) { return c.mode == static_cast<int>(ModeId::Locomotion); }))
          sweep.fail("sweep.gait", "sets the gait of the script's walking commands (mode 11), but the script has none");
        break;
      case AxisKind::PushImpulse: axis.values = number_list(sweep, node, "sweep", axis.name, 0, kMaxImpulseNs, false); break;
      case AxisKind::PushDirection: axis.values = number_list(sweep, node, "sweep", axis.name, -360, 360, false); break;
      case AxisKind::PushAt: axis.values = number_list(sweep, node, "sweep", axis.name, 0, kScenarioMaxDurationS, false); break;
      case AxisKind::Terrain: read_terrain_axis(sweep, node, base_dir, axis); break;
      case AxisKind::JumpOrMotionId: {
        axis.values = number_list(sweep, node, "sweep", axis.name, 0, 255, true);
        const bool jumps = std::any_of(s.commands.begin(), s.commands.end(), is_jump);
        const bool motions = std::any_of(s.commands.begin(), s.commands.end(), is_motion);
        if (!jumps && !motions)
          sweep.fail("sweep." + axis.name, "sets the gait_id of the script's jumps (mode 16) and named motions "
                                           "(mode 62), but the script has none");
        for (std::size_t i = 0; i < axis.values.size(); ++i)
          if (jumps && !known_jump_id(static_cast<int>(axis.values[i])))
            sweep.fail(indexed("sweep." + axis.name, i), "is not a jump id of mode 16 (" + jump_ids() + ")");
        break;
      }
    }
    const bool push_axis = axis.kind == AxisKind::PushImpulse || axis.kind == AxisKind::PushDirection ||
                           axis.kind == AxisKind::PushAt;
    if (push_axis && s.pushes.empty())
      sweep.fail("sweep." + axis.name, "sets a field of every push, but the scenario has no pushes: list them under pushes:");
    axes.push_back(axis);
  }
  if (axes.empty()) sweep.fail("sweep", "has no axes; give at least one of: " + join_words(accepted) + ", or leave sweep: out");
  return axes;
}

}  // namespace

const std::array<const char*, 7>& axis_names() {
  static constexpr std::array<const char*, 7> kNames{"seed",      "gait",    "push_impulse_n_s", "push_direction_deg",
                                                     "push_at_s", "terrain", "jump_or_motion_id"};
  return kNames;
}

SweepSpec parse_scenario(const std::string& text, const std::string& name, const std::string& base_dir) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ConfigError(std::string(kKind) + " " + name + ": not valid YAML: " + e.what());
  }
  if (!root.IsMap()) throw ConfigError(std::string(kKind) + " " + name + ": must be a mapping of keys (docs/sweeps.md)");
  const SectionReader top(root, name, "<top>",
                          {"robot", "seed", "duration_s", "end_after_last_push_s", "commands", "soak", "pushes",
                           "faults", "settle_speed_m_s", "sweep", "terrain"},
                          kKind);
  SweepSpec spec;
  Scenario& s = spec.base;
  s.file = name;
  if (top.has("robot")) read_robot(root["robot"], name, base_dir, s);
  if (top.has("terrain")) s.terrain = read_terrain(top, base_dir);
  top.unsigned_integer("seed", s.seed);
  if (!top.has("duration_s") && !top.has("end_after_last_push_s"))
    top.fail("duration_s", "is missing: give duration_s (robot seconds of a run) or end_after_last_push_s");
  top.number("duration_s", s.duration_s, 0.01, kScenarioMaxDurationS);
  top.number("end_after_last_push_s", s.end_after_last_push_s, 0.0, kScenarioMaxDurationS);
  const double latest_s = top.has("end_after_last_push_s") ? kScenarioMaxDurationS : s.duration_s;
  top.number("settle_speed_m_s", s.settle_speed_m_s, 0.0, kMaxSpeedMs);
  if (top.has("commands")) s.commands = read_commands(top, root["commands"], name, latest_s);
  if (top.has("soak")) s.soak = read_soak(root["soak"], name);
  if (s.commands.empty() && !s.soak) top.fail("commands", "is missing: give a command script (commands:) or a soak (soak:)");
  if (top.has("pushes")) s.pushes = read_pushes(top, root["pushes"], name, latest_s);
  if (top.has("end_after_last_push_s") && s.pushes.empty())
    top.fail("end_after_last_push_s", "needs pushes: to end after");
  if (top.has("faults")) s.faults = read_faults(top, root["faults"], name, latest_s);
  if (top.has("sweep")) spec.axes = read_axes(root["sweep"], name, base_dir, s);
  return spec;
}

SweepSpec load_scenario(const std::string& path) {
  if (std::filesystem::is_directory(path))
    throw ConfigError(std::string(kKind) + " " + path + ": is a folder; give the YAML file");
  std::string error;
  const std::optional<std::string> text = read_text_file(path, kScenarioMaxBytes, error);
  if (!text) throw ConfigError(std::string(kKind) + " " + path + ": " + error);
  return parse_scenario(*text, path, std::filesystem::path(path).parent_path().string());
}

}  // namespace cerebellum
