// The body state estimator as the control loop's estimator in lockstep simulation, against the
// simulator's ground truth: standing, and following a push.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "loop/control_loop.hpp"
#include "backend/mujoco_backend.hpp"
#include "control/stand_up_controller.hpp"
#include "estimation/body_state_estimator.hpp"

namespace cerebellum {
namespace {

MujocoBackendConfig sim_config(bool noise) {
  MujocoBackendConfig config;
  config.model_path = std::string(CEREBELLUM_MODEL_DIR) + "/cyberdog2.xml";
  config.initial_height_m = 0.3;
  config.noise.enabled = noise;
  config.noise.seed = 3;
  return config;
}

// worst disagreement between estimate and truth over a stretch of cycles
struct TrackingErrors {
  double height_m = 0.0;
  double position_z_m = 0.0;
  double velocity_m_s = 0.0;
  double peak_true_speed_m_s = 0.0;
  bool always_valid = true;
};

// each cycle, before the physics runs on, compares the estimate with the simulator's truth
class TruthComparison final : public CycleObserver {
 public:
  explicit TruthComparison(const MujocoBackend& backend) : backend_(backend) {}

  void on_cycle(const CycleRecord& record) override {
    const GroundTruth truth = backend_.ground_truth();
    const Eigen::Vector3d true_velocity(truth.velocity_world[0], truth.velocity_world[1], truth.velocity_world[2]);
    const RobotState& state = record.state;
    errors.height_m = std::max(errors.height_m, std::abs(state.height_m - truth.position[2]));
    errors.position_z_m = std::max(errors.position_z_m, std::abs(state.position_world.z() - truth.position[2]));
    errors.velocity_m_s = std::max(errors.velocity_m_s, (state.velocity_world - true_velocity).norm());
    errors.peak_true_speed_m_s = std::max(errors.peak_true_speed_m_s, true_velocity.norm());
    errors.always_valid &= state.valid;
  }

  TrackingErrors errors;

 private:
  const MujocoBackend& backend_;
};

// the robot dropped from 0.3 m stands up and holds the stand pose, estimated by the filter
struct EstimatedStand {
  explicit EstimatedStand(bool noise)
      : backend(sim_config(noise)),
        stand_up(default_stand_up_config()),
        loop(backend, estimator, stand_up, GuardLimits{}, 0.002),
        truth(backend) {
    loop.add_observer(truth);
  }

  void run_for(double seconds) {
    const double end = backend.time_s() + seconds - 1e-9;
    while (backend.time_s() < end) loop.tick();
  }

  MujocoBackend backend;
  BodyStateEstimator estimator;
  StandUpController stand_up;
  ControlLoop loop;
  TruthComparison truth;
};

TEST(BodyStateEstimatorSim, StandingHeightAndVelocityAgreeWithTheSimulator) {
  for (const bool noise : {false, true}) {
    SCOPED_TRACE(noise ? "with sensor noise" : "without sensor noise");
    EstimatedStand sim(noise);
    sim.run_for(3.0);
    ASSERT_NEAR(sim.stand_up.progress(), 1.0, 1e-12);
    sim.truth.errors = {};
    sim.run_for(2.0);
    EXPECT_TRUE(sim.truth.errors.always_valid);
    EXPECT_LT(sim.truth.errors.height_m, 0.01);
    EXPECT_LT(sim.truth.errors.position_z_m, 0.01);
    EXPECT_LT(sim.truth.errors.velocity_m_s, 0.05);
  }
}

TEST(BodyStateEstimatorSim, VelocityFollowsAPush) {
  for (const std::array<double, 3>& push_n : {std::array<double, 3>{40.0, 0.0, 0.0}, {0.0, -50.0, 0.0}}) {
    SCOPED_TRACE(push_n[0] != 0.0 ? "forward push" : "sideways push");
    EstimatedStand sim(true);
    sim.run_for(3.0);
    sim.truth.errors = {};
    sim.backend.set_external_force(push_n);
    sim.run_for(0.2);
    sim.backend.set_external_force({0.0, 0.0, 0.0});
    sim.run_for(1.0);
    EXPECT_TRUE(sim.truth.errors.always_valid);
    // the push moved the robot noticeably: the tracking check has something to track
    EXPECT_GT(sim.truth.errors.peak_true_speed_m_s, 0.15);
    EXPECT_LT(sim.truth.errors.velocity_m_s, 0.1);
  }
}

}  // namespace
}  // namespace cerebellum
