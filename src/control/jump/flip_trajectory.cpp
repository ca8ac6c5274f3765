#include "control/jump/flip_trajectory.hpp"

#include <cmath>
#include <sstream>

#include "core/number_text.hpp"
#include "core/robot_model.hpp"
#include "core/text_file.hpp"

namespace cerebellum {
namespace {

constexpr const char* kMotorNames[kFlipMotors] = {"front_hip", "front_knee", "rear_hip", "rear_knee"};
constexpr int kColumns = 5 + 3 * kFlipMotors;
// a flip of a few hundred knots is a few tens of kilobytes
constexpr std::size_t kMaxFileBytes = 1 << 20;

std::vector<std::string> split_csv(std::string_view line) {
  std::vector<std::string> fields;
  std::string field;
  for (char c : line) {
    if (c == ',') {
      fields.push_back(field);
      field.clear();
    } else if (c != '\r') {
      field.push_back(c);
    }
  }
  fields.push_back(field);
  return fields;
}

// the motor's joint range: front pair = leg 0 (front right), rear pair = leg 2 (rear right)
robot::JointRange motor_range(int motor) {
  const std::size_t leg = motor < 2 ? 0 : 2;
  return robot::joint_range(leg * kJointsPerLeg + 1 + static_cast<std::size_t>(motor % 2));
}

}  // namespace

std::string flip_trajectory_header() {
  std::string header = "time_s,phase,trunk_x_m,trunk_z_m,trunk_pitch_rad";
  for (const char* name : kMotorNames) header += std::string(",q_") + name + "_rad";
  for (const char* name : kMotorNames) header += std::string(",qd_") + name + "_rad_s";
  for (const char* name : kMotorNames) header += std::string(",tau_") + name + "_nm";
  return header;
}

std::string flip_trajectory_text(const FlipTrajectory& trajectory, const std::vector<std::string>& comment) {
  std::string text;
  for (const std::string& line : comment) text += "# " + line + "\n";
  text += flip_trajectory_header() + "\n";
  for (const FlipSample& s : trajectory.samples) {
    text += number_text(s.time_s, 9) + "," + std::to_string(s.phase);
    for (double v : s.trunk) text += "," + number_text(v, 9);
    for (double v : s.q_rad) text += "," + number_text(v, 9);
    for (double v : s.qd_rad_s) text += "," + number_text(v, 9);
    for (double v : s.tau_nm) text += "," + number_text(v, 9);
    text += "\n";
  }
  return text;
}

std::optional<FlipTrajectory> parse_flip_trajectory(std::string_view text, double torque_max_nm, std::string& error) {
  FlipTrajectory trajectory;
  std::istringstream lines{std::string(text)};
  std::string line;
  int line_number = 0;
  bool header_seen = false;
  const auto fail = [&](const std::string& what) {
    error = "line " + std::to_string(line_number) + ": " + what;
    return std::nullopt;
  };
  while (std::getline(lines, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    if (!header_seen) {
      if (line != flip_trajectory_header()) return fail("the header is not \"" + flip_trajectory_header() + "\"");
      header_seen = true;
      continue;
    }
    const std::vector<std::string> fields = split_csv(line);
    if (static_cast<int>(fields.size()) != kColumns)
      return fail(std::to_string(fields.size()) + " columns, the header has " + std::to_string(kColumns));
    double values[kColumns];
    for (int c = 0; c < kColumns; ++c) {
      const std::optional<double> value = finite_number(fields[c]);
      if (!value) return fail("column " + std::to_string(c + 1) + " (\"" + fields[c] + "\") is not a finite number");
      values[c] = *value;
    }
    FlipSample s{};
    s.time_s = values[0];
    if (values[1] != 0.0 && values[1] != 1.0 && values[1] != 2.0) return fail("phase " + fields[1] + " is not 0, 1 or 2");
    s.phase = static_cast<int>(values[1]);
    for (int i = 0; i < 3; ++i) s.trunk[i] = values[2 + i];
    for (int m = 0; m < kFlipMotors; ++m) {
      s.q_rad[m] = values[5 + m];
      s.qd_rad_s[m] = values[5 + kFlipMotors + m];
      s.tau_nm[m] = values[5 + 2 * kFlipMotors + m];
      const robot::JointRange range = motor_range(m);
      if (s.q_rad[m] < range.lower || s.q_rad[m] > range.upper)
        return fail(std::string(kMotorNames[m]) + " at " + fields[5 + m] + " rad, outside its range " +
                    number_text(range.lower, 4) + ".." + number_text(range.upper, 4));
      if (std::abs(s.tau_nm[m]) > torque_max_nm)
        return fail(std::string(kMotorNames[m]) + " torque " + fields[5 + 2 * kFlipMotors + m] + " Nm beyond the motors' " +
                    number_text(torque_max_nm, 4) + " Nm");
    }
    if (!trajectory.samples.empty()) {
      const FlipSample& last = trajectory.samples.back();
      if (s.time_s <= last.time_s) return fail("time " + fields[0] + " s does not increase");
      if (s.phase < last.phase) return fail("phase " + fields[1] + " goes back");
    } else if (s.time_s != 0.0) {
      return fail("the first row's time is " + fields[0] + " s, not 0");
    }
    trajectory.samples.push_back(s);
  }
  if (!header_seen) {
    error = "no header line";
    return std::nullopt;
  }
  if (trajectory.samples.size() < 2) {
    error = "fewer than two rows";
    return std::nullopt;
  }
  return trajectory;
}

std::optional<FlipTrajectory> read_flip_trajectory(const std::string& path, double torque_max_nm, std::string& error) {
  const std::optional<std::string> text = read_text_file(path, kMaxFileBytes, error);
  if (!text) {
    error = path + " " + error;
    return std::nullopt;
  }
  std::optional<FlipTrajectory> trajectory = parse_flip_trajectory(*text, torque_max_nm, error);
  if (!trajectory) error = path + ": " + error;
  return trajectory;
}

}  // namespace cerebellum
