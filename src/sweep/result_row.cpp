#include "sweep/result_row.hpp"

#include <cstdio>
#include <sstream>

#include "sweep/sweep_grid.hpp"

namespace cerebellum {

namespace {

// fixed decimals: the same number always prints the same, so rows of two machines compare as text
std::string decimal(double v, int places) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", places, v);
  return buffer;
}

}  // namespace

std::string axis_value(const Axis& axis, double v) {
  if (axis.kind == AxisKind::Terrain) return axis.terrains.at(static_cast<std::size_t>(v)).text;
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.10g", v);
  return buffer;
}

std::string result_header(const SweepSpec& spec) {
  std::string h = "cell";
  // a seed axis is the seed column itself
  for (const Axis& axis : spec.axes)
    if (axis.kind != AxisKind::Seed) h += "," + axis.name;
  return h +
         ",seed,outcome,robot_time_s,ticks,commands,faults,pushes,falls,first_fall_s,falls_no_fault_near,"
         "falls_not_safe,protections,non_finite_commands,max_tilt_deg,end_speed_m_s,end_mode,distance_m";
}

std::string result_row(const SweepSpec& spec, std::uint64_t cell, const RunResult& r) {
  std::string row = std::to_string(cell);
  const std::vector<double> values = cell_values(spec, cell);
  for (std::size_t a = 0; a < values.size(); ++a)
    if (spec.axes[a].kind != AxisKind::Seed) row += "," + axis_value(spec.axes[a], values[a]);
  const Scenario s = cell_scenario(spec, cell);
  row += "," + std::to_string(s.seed) + "," + r.outcome + "," + decimal(r.robot_time_s, 3) + "," +
         std::to_string(r.ticks) + "," + std::to_string(r.commands) + "," + std::to_string(r.faults) + "," +
         std::to_string(r.pushes) + "," + std::to_string(r.falls) + "," + decimal(r.first_fall_s, 3) + "," +
         std::to_string(r.falls_no_fault_near) + "," + std::to_string(r.falls_not_safe) + "," +
         std::to_string(r.protections) + "," + std::to_string(r.non_finite_commands) + "," +
         decimal(r.max_tilt_deg, 2) + "," + decimal(r.end_speed_m_s, 3) + "," + std::to_string(r.end_mode) + "," +
         decimal(r.distance_m, 3);
  return row;
}

std::vector<std::string> csv_fields(const std::string& row) {
  std::vector<std::string> fields;
  std::stringstream in(row);
  for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
  if (!row.empty() && row.back() == ',') fields.emplace_back();
  return fields;
}

int column_index(const std::string& header, const std::string& column) {
  const std::vector<std::string> names = csv_fields(header);
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == column) return static_cast<int>(i);
  return -1;
}

}  // namespace cerebellum
