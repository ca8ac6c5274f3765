#include "motions/user_gait_convert.hpp"

#include <toml++/toml.h>

#include <array>
#include <cmath>
#include <sstream>

#include "motions/user_gait_file.hpp"
#include "motions/command_step_toml.hpp"

namespace cerebellum {
namespace {

template <std::size_t N>
bool read_numbers(const toml::table& table, std::string_view key, std::size_t index, std::array<double, N>& out,
                  TomlProblem& problem) {
  const toml::array* array = table[key].as_array();
  if (array == nullptr || array->size() != N) {
    problem.set(toml_where("step", index, key) + " must be a list of " + std::to_string(N) + " numbers");
    return false;
  }
  for (std::size_t k = 0; k < N; ++k) {
    const std::optional<double> value = array->get(k)->value<double>();
    if (!value || !std::isfinite(*value)) {
      problem.set(toml_where("step", index, key) + " must be a list of " + std::to_string(N) + " finite numbers");
      return false;
    }
    out[k] = *value;
  }
  return true;
}

double read_number(const toml::table& table, std::string_view key, std::size_t index, TomlProblem& problem) {
  const std::optional<double> value = table[key].value<double>();
  if (!value || !std::isfinite(*value)) {
    problem.set(toml_where("step", index, key) + " must be a finite number");
    return 0.0;
  }
  return *value;
}

template <typename Array>
std::string list(const Array& values) {
  std::ostringstream out;
  out.precision(9);
  out << '[';
  for (std::size_t i = 0; i < values.size(); ++i) out << (i ? ", " : "") << static_cast<double>(values[i]);
  out << ']';
  return out.str();
}

}  // namespace

bool is_converted_gait_parameters(std::string_view text) {
  // a converted step has a mode key; a human one has type = "usergait"
  std::size_t at = 0;
  while ((at = text.find("mode", at)) != std::string_view::npos) {
    const bool line_start = at == 0 || text[at - 1] == '\n';
    std::size_t after = at + 4;
    while (after < text.size() && (text[after] == ' ' || text[after] == '\t')) ++after;
    if (line_start && after < text.size() && text[after] == '=') return true;
    at += 4;
  }
  return false;
}

UserGaitConversion convert_gait_parameters(std::string_view human_text) {
  UserGaitConversion result;
  if (human_text.substr(0, kGaitParametersHeader.size()) != kGaitParametersHeader) {
    result.error = "does not begin with '# Gait Params'";
    return result;
  }
  const std::optional<toml::table> parsed = parse_toml_document(human_text, result.error);
  if (!parsed) return result;
  const toml::table& document = *parsed;
  TomlProblem problem;
  const toml::array* steps = toml_entries(document, "step", kMaxGaitEntries, {}, problem);
  std::ostringstream out;
  out.precision(9);
  out << kGaitParametersHeader << "\n";
  for (std::size_t i = 0; steps != nullptr && i < steps->size(); ++i) {
    const toml::table& step = *steps->get(i)->as_table();
    check_toml_keys(step,
                    {"type", "body_vel_des", "body_pos_des", "landing_pos_des", "step_height", "weight", "use_mpc_traj",
                     "mu", "landing_gain", "gait_id", "duration"},
                    "step", i, problem);
    if (step["type"].value<std::string_view>() != "usergait") {
      problem.set(toml_where("step", i, "type") + " must be \"usergait\"");
    }
    std::array<double, 3> velocity{};
    std::array<double, 6> pose{};
    std::array<double, 12> landing{};
    std::array<double, 4> height{};
    std::array<double, 6> weight{};
    read_numbers(step, "body_vel_des", i, velocity, problem);
    read_numbers(step, "body_pos_des", i, pose, problem);
    read_numbers(step, "landing_pos_des", i, landing, problem);
    read_numbers(step, "step_height", i, height, problem);
    read_numbers(step, "weight", i, weight, problem);
    const double mu = read_number(step, "mu", i, problem);
    const double landing_gain = read_number(step, "landing_gain", i, problem);
    const std::optional<long long> use_mpc = toml_integer_in(step.get("use_mpc_traj"), 0, 1);
    if (!use_mpc) problem.set(toml_where("step", i, "use_mpc_traj") + " must be 0 or 1");
    const std::optional<long long> gait = toml_integer_in(step.get("gait_id"), 110, 110);
    if (!gait) problem.set(toml_where("step", i, "gait_id") + " must be 110");
    const std::optional<long long> duration = toml_integer_in(step.get("duration"), 1, 2147483647);
    if (!duration) problem.set(toml_where("step", i, "duration") + " must be an integer > 0 (ms)");
    for (double h : height) {
      if (h < 0.0 || h > 0.999) problem.set(toml_where("step", i, "step_height") + " values must be in [0, 0.999] m");
    }
    if (landing_gain < 0.0 || landing_gain > 12.7) {
      problem.set(toml_where("step", i, "landing_gain") + " must be in [0, 12.7] (sent as an int8 of gain x 10)");
    }
    if (problem.found()) break;
    // the seed's conversion, field for field
    const std::array<double, 3> rpy{pose[0], pose[1], pose[2]};
    const std::array<double, 3> position{pose[3], pose[4], pose[5]};
    const std::array<double, 6> foot_pose{landing[0], landing[1], landing[3], landing[4], landing[6], landing[7]};
    const std::array<double, 3> ctrl_point{landing[9], landing[10], mu};
    const std::array<double, 2> packed{std::ceil(height[0] * 1e3) + std::ceil(height[1] * 1e3) * 1e3,
                                       std::ceil(height[2] * 1e3) + std::ceil(height[3] * 1e3) * 1e3};
    out << "\n[[step]]\nmode = 11\ngait_id = 110\ncontact = " << static_cast<int>(std::floor(landing_gain * 10.0))
        << "\nlife_count = 0\nvel_des = " << list(velocity) << "\nrpy_des = " << list(rpy)
        << "\npos_des = " << list(position) << "\nacc_des = " << list(weight) << "\nctrl_point = " << list(ctrl_point)
        << "\nfoot_pose = " << list(foot_pose) << "\nstep_height = " << list(packed) << "\nvalue = " << *use_mpc
        << "\nduration = " << *duration << "\n";
  }
  if (problem.found()) {
    result.error = problem.text();
    return result;
  }
  result.text = out.str();
  return result;
}

}  // namespace cerebellum
