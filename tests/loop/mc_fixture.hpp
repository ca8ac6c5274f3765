// Shared by the lockstep tests of the whole MC.
#pragma once

#include <algorithm>
#include <cmath>

#include "loop/mc_config.hpp"
#include "loop/lockstep_client.hpp"

namespace cerebellum::testing {

// the angle between the trunk's z axis and the world's, on the simulator's truth
inline double truth_tilt_rad(const GroundTruth& truth) {
  const auto& q = truth.quat;
  return std::acos(std::clamp(1.0 - 2.0 * (q[1] * q[1] + q[2] * q[2]), -1.0, 1.0));
}

// the robot starts lying, the motors off; with a seed, the sensors carry that seed's noise
inline McConfig lying_start(bool noise = false, unsigned seed = 0) {
  McConfig config = default_config();
  config.startup = Startup::Off;
  config.robot.noise.enabled = noise;
  config.robot.noise.seed = seed;
  return config;
}

// a high-level command with a forward speed and a yaw rate
inline HighLevelCommand command(ModeId mode, int gait, double vx = 0.0, double yaw_rate = 0.0) {
  return high_level_command(mode, gait, vx, 0.0, yaw_rate);
}

}  // namespace cerebellum::testing
