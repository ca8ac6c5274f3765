// Shared set-up for simulation tests: the project's model and a lockstep loop around it.
#pragma once

#include <memory>
#include <string>

#include "app/control_loop.hpp"
#include "backend/mujoco_backend.hpp"
#include "estimation/kinematic_estimator.hpp"

namespace cerebellum::testing {

inline std::string model_path() { return std::string(CEREBELLUM_MODEL_DIR) + "/cyberdog2.xml"; }

inline MujocoBackendConfig sim_config(double initial_height_m = 0.3, bool noise = false, unsigned seed = 0) {
  MujocoBackendConfig config;
  config.model_path = model_path();
  config.initial_height_m = initial_height_m;
  config.noise.enabled = noise;
  config.noise.seed = seed;
  return config;
}

// a backend, an estimator and a loop for one controller, stepped in lockstep
struct LockstepSim {
  LockstepSim(const MujocoBackendConfig& config, MotionController& controller)
      : backend(config), loop(backend, estimator, controller, GuardLimits{}, 0.002) {}

  void run_for(double seconds) {
    const double end = backend.time_s() + seconds - 1e-9;
    while (backend.time_s() < end) loop.tick();
  }

  MujocoBackend backend;
  KinematicEstimator estimator;
  ControlLoop loop;
};

}  // namespace cerebellum::testing
