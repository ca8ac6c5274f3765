// What the soak benchmarks share: the simulated robot they run on, their random walking
// commands and their judgement of a fall (on the simulator's truth).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "loop/mc_config.hpp"
#include "backend/simulation.hpp"
#include "control/locomotion/gait.hpp"

namespace cerebellum::bench {

// the angle between the trunk's up axis and the vertical
inline double tilt_rad(const GroundTruth& g) {
  const double up_z = 1 - 2 * (g.quat[1] * g.quat[1] + g.quat[2] * g.quat[2]);
  return std::acos(std::clamp(up_z, -1.0, 1.0));
}

// the trunk's up axis within 0.6 rad (34 deg) of vertical
inline bool upright(const GroundTruth& g) { return tilt_rad(g) < 0.6; }

// a walking command whose trunk tilted past this (20 deg; the bound pitches up to 0.3 rad when
// it turns at full speed) and still walked on: a near fall
inline constexpr double kNearFallTiltRad = 0.35;

// the default robot lying at start; with sensor noise of the given seed, or without (seed < 0)
inline McConfig soak_config(long noise_seed = -1) {
  McConfig config = default_config();
  config.startup = Startup::Off;
  config.robot.model_path = std::string(CEREBELLUM_MODEL_DIR) + "/cyberdog2.xml";
  if (noise_seed >= 0) {
    config.robot.noise.enabled = true;
    config.robot.noise.seed = static_cast<unsigned>(noise_seed);
  }
  return config;
}

struct WalkCommand {
  int gait = 0;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // vx, vy (m/s), yaw rate (rad/s)
};

// one of the gaits, and a velocity drawn uniformly within that gait's limits
inline WalkCommand random_walk_command(std::mt19937& rng, const std::vector<int>& gaits) {
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

}  // namespace cerebellum::bench
