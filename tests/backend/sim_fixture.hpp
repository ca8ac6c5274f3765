// Shared set-up for simulation tests: the project's model and a lockstep loop around it.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include <Eigen/Geometry>

#include "loop/control_loop.hpp"
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

// roll, pitch, yaw (ZYX) of the simulator's trunk orientation, from its rotation matrix: the tests'
// own check, independent of the MC's rpy_from_quaternion
inline Eigen::Vector3d truth_rpy(const GroundTruth& truth) {
  const Eigen::Matrix3d r =
      Eigen::Quaterniond(truth.quat[0], truth.quat[1], truth.quat[2], truth.quat[3]).toRotationMatrix();
  return {std::atan2(r(2, 1), r(2, 2)), std::asin(-std::clamp(r(2, 0), -1.0, 1.0)), std::atan2(r(1, 0), r(0, 0))};
}

// the trunk's x axis above the horizontal (rad): 0 level, pi/2 nose straight up, more past it
inline double truth_elevation(const GroundTruth& truth) {
  const double w = truth.quat[0], x = truth.quat[1], y = truth.quat[2], z = truth.quat[3];
  return std::atan2(2.0 * (x * z - w * y), 1.0 - 2.0 * (y * y + z * z));
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
