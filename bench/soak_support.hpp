// What the soak benchmarks share: the simulated robot they run on, their random walking
// commands and their judgement of a fall (on the simulator's truth, from src/sweep/).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "loop/mc_config.hpp"
#include "sweep/random_soak.hpp"

namespace cerebellum::bench {

// the fall judgement and the random walking command live in src/sweep/, shared with `cerebellum
// sweep`'s soak; the benchmarks keep their names for them
using cerebellum::kNearFallTiltRad;
using cerebellum::random_walk_command;
using cerebellum::tilt_rad;
using cerebellum::upright;
using cerebellum::WalkCommand;

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

}  // namespace cerebellum::bench
