// A simulated robot that stands up, then walks with the locomotion controller on its own
// estimate (BodyStateEstimator fed by the loop with the gait's contact plan), in lockstep time.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "loop/control_loop.hpp"
#include "backend/mujoco_backend.hpp"
#include "control/locomotion/locomotion_controller.hpp"
#include "control/qp/goldfarb_idnani_solver.hpp"
#include "control/stand_up_controller.hpp"
#include "core/orientation.hpp"
#include "estimation/body_state_estimator.hpp"

namespace cerebellum::testing {

class StandThenWalk final : public MotionController {
 public:
  explicit StandThenWalk(std::unique_ptr<qp::QpSolver> solver, const LocomotionConfig& config = {})
      : stand_(default_stand_up_config()), walk_(config, std::move(solver)) {}

  void compute(const RobotState& state, JointCommand& command) override {
    if (state.time_s < kStandSeconds) {
      stand_.compute(state, command);
      return;
    }
    if (!walking_) {
      walking_ = true;
      walk_.set_command(command_);
      walk_.reset(state);
    }
    walk_.compute(state, command);
  }
  ContactPlan contact_plan() const override {
    if (!walking_) return std::nullopt;
    return walk_.contact_schedule();
  }

  bool set(const LocomotionTarget& command) {
    command_ = command;
    return !walking_ || walk_.set_command(command);
  }
  LocomotionController& walker() { return walk_; }

  static constexpr double kStandSeconds = 3.0;

 private:
  StandUpController stand_;
  LocomotionController walk_;
  LocomotionTarget command_;
  bool walking_ = false;
};

inline LocomotionTarget walk_command(int gait, double vx, double vy = 0.0, double yaw_rate = 0.0) {
  LocomotionTarget command;
  command.gait = *gait_pattern(gait);
  command.velocity = {vx, vy, yaw_rate};
  return command;
}

struct WalkingSim {
  explicit WalkingSim(std::unique_ptr<qp::QpSolver> solver = std::make_unique<qp::GoldfarbIdnaniSolver>(),
                      const LocomotionConfig& locomotion = {})
      : backend(config()),
        controller(std::move(solver), locomotion),
        loop(backend, estimator, controller, GuardLimits{}, 0.002) {}

  static MujocoBackendConfig config() {
    MujocoBackendConfig c;
    c.model_path = std::string(CEREBELLUM_MODEL_DIR) + "/cyberdog2.xml";
    return c;
  }
  // run until robot time t; fails the callback's expectations as it goes
  template <typename EachTick>
  void run_until(double t, EachTick&& each_tick) {
    while (backend.time_s() < t - 1e-9) each_tick(loop.tick());
  }
  void run_until(double t) {
    run_until(t, [](const CycleRecord&) {});
  }
  // the trunk's roll, pitch, yaw on the simulator's truth
  Eigen::Vector3d rpy_truth() const {
    const GroundTruth g = backend.ground_truth();
    return rpy_from_quaternion(Eigen::Quaterniond(g.quat[0], g.quat[1], g.quat[2], g.quat[3]));
  }
  double yaw_truth() const { return rpy_truth().z(); }
  // the angle between the trunk's up axis and the vertical, on the simulator's truth
  double tilt_truth() const {
    const GroundTruth g = backend.ground_truth();
    return std::acos(std::clamp(1 - 2 * (g.quat[1] * g.quat[1] + g.quat[2] * g.quat[2]), -1.0, 1.0));
  }
  bool upright() const {
    // the body's z axis within ~30 deg of vertical and the trunk well above the ground
    return tilt_truth() < 0.5 && backend.ground_truth().position[2] > 0.17;
  }

  MujocoBackend backend;
  BodyStateEstimator estimator;
  StandThenWalk controller;
  ControlLoop loop;
};

}  // namespace cerebellum::testing
