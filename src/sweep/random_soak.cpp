#include "sweep/random_soak.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "control/locomotion/gait.hpp"

namespace cerebellum {

double tilt_rad(const GroundTruth& g) {
  const double up_z = 1 - 2 * (g.quat[1] * g.quat[1] + g.quat[2] * g.quat[2]);
  return std::acos(std::clamp(up_z, -1.0, 1.0));
}

WalkCommand random_walk_command(std::mt19937& rng, const std::vector<int>& gaits) {
  // int draws as the soaks always drew them: a seed's figures stay comparable
  std::uniform_int_distribution<int> pick(0, static_cast<int>(gaits.size()) - 1);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  WalkCommand command;
  command.gait = gaits[static_cast<std::size_t>(pick(rng))];
  const GaitPattern p = *gait_pattern(command.gait);
  for (int axis = 0; axis < 3; ++axis) {
    const double r = unit(rng);
    command.velocity[axis] = r >= 0 ? r * p.velocity_max[axis] : -r * p.velocity_min[axis];
  }
  return command;
}

std::string random_fault(std::mt19937& rng) {
  std::uniform_int_distribution<int> motor(0, 11), leg(0, 3), kind(0, 13);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::string m = "motor ";
  m += std::to_string(motor(rng));
  const auto number = [&](double lower, double upper) { return std::to_string(lower + (upper - lower) * unit(rng)); };
  switch (kind(rng)) {
    case 0: return m + " disconnected";
    case 1: return m + " over_temperature";
    case 2: return m + " driver_fault";
    case 3: return m + " encoder_lost";
    case 4: return m + " overload";
    case 5: return m + " stuck";
    case 6: return m + " derated " + number(0.3, 0.9);
    case 7: return std::string("imu bias ") + number(-0.05, 0.05);
    case 8: return "imu stuck";
    case 9: return "imu dropout";
    case 10: return "imu nan";
    case 11: return std::string("battery sag ") + number(2.0, 8.0);
    case 12: return std::string("battery soc ") + number(0.0, 3.0);
    default: {
      std::string foot = "foot ";
      foot += std::to_string(leg(rng));
      return foot + " slippery " + number(0.05, 0.25);
    }
  }
}

std::string fault_kind_name(const std::string& fault) {
  std::istringstream in(fault);
  std::vector<std::string> words;
  for (std::string word; in >> word;) words.push_back(word);
  if (words.empty()) return "";
  if ((words[0] == "motor" || words[0] == "foot") && words.size() > 2) return words[0] + " " + words[2];
  return words.size() > 1 ? words[0] + " " + words[1] : words[0];
}

}  // namespace cerebellum
