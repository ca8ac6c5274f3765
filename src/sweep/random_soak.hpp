// The random draws of the soaks (the sweep's soak and bench/'s soaks share them, so a seed's
// figures stay comparable): a walking command within a gait's limits, a fault of the fault
// grammar, and the judgement of a fall on the simulator's truth.
#pragma once

#include <Eigen/Core>
#include <random>
#include <string>
#include <vector>

#include "backend/simulation.hpp"

namespace cerebellum {

// the angle between the trunk's up axis and the vertical
double tilt_rad(const GroundTruth& g);

// the trunk's up axis within 0.6 rad (34 deg) of vertical
inline constexpr double kFallTiltRad = 0.6;
inline bool upright(const GroundTruth& g) { return tilt_rad(g) < kFallTiltRad; }

// a walking command whose trunk tilted past this (20 deg; the bound pitches up to 0.3 rad when
// it turns at full speed) and still walked on: a near fall
inline constexpr double kNearFallTiltRad = 0.35;

struct WalkCommand {
  int gait = 0;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // vx, vy (m/s), yaw rate (rad/s)
};

// one of the gaits, and a velocity drawn uniformly within that gait's limits
WalkCommand random_walk_command(std::mt19937& rng, const std::vector<int>& gaits);

// a random fault in the grammar of backend/fault_request.hpp, without its length
std::string random_fault(std::mt19937& rng);

// "motor 3 derated 0.5" -> "motor derated"; "imu stuck" -> "imu stuck"; "foot 2 slippery .." -> "foot slippery"
std::string fault_kind_name(const std::string& fault);

}  // namespace cerebellum
