// The body state estimator's drift and cost. Drift: the robot stands up (3 s) and stands for 60 s
// of robot time with sensor noise on, in lockstep simulation; the counters give the position
// error against the simulator's truth at the end and how much it changed over the 60 s. Cost: one
// Kalman filter update (predict + correct) and one whole estimator update per control tick.
#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <random>
#include <string>
#include <vector>

#include "loop/control_loop.hpp"
#include "backend/mujoco_backend.hpp"
#include "control/stand_up_controller.hpp"
#include "core/robot_model.hpp"
#include "estimation/body_state_estimator.hpp"

namespace {

using namespace cerebellum;

constexpr double kStandUpS = 3.0;
constexpr double kStandingS = 60.0;

Eigen::Vector3d true_position(const MujocoBackend& backend) {
  const GroundTruth truth = backend.ground_truth();
  return {truth.position[0], truth.position[1], truth.position[2]};
}

Eigen::Vector3d true_velocity(const MujocoBackend& backend) {
  const GroundTruth truth = backend.ground_truth();
  return {truth.velocity_world[0], truth.velocity_world[1], truth.velocity_world[2]};
}

// one iteration = stand up, then 60 s standing; arg: the sensor noise seed
void BM_StandingDrift60s(benchmark::State& bench) {
  Eigen::Vector3d error_start = Eigen::Vector3d::Zero();
  Eigen::Vector3d error_end = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_error = Eigen::Vector3d::Zero();
  double height_error_m = 0.0;
  for (auto _ : bench) {
    MujocoBackendConfig config;
    config.model_path = std::string(CEREBELLUM_MODEL_DIR) + "/cyberdog2.xml";
    config.noise.enabled = true;
    config.noise.seed = static_cast<unsigned>(bench.range(0));
    MujocoBackend backend(config);
    BodyStateEstimator estimator;
    StandUpController stand_up(default_stand_up_config());
    ControlLoop loop(backend, estimator, stand_up, GuardLimits{}, 0.002);
    // a tick estimates the instant it reads, before the physics runs on: truth first, then tick
    while (backend.time_s() < kStandUpS - 1e-9) loop.tick();
    const Eigen::Vector3d truth_start = true_position(backend);
    error_start = loop.tick().state.position_world - truth_start;
    while (backend.time_s() < kStandUpS + kStandingS - 1e-9) loop.tick();
    const Eigen::Vector3d truth_end = true_position(backend);
    const Eigen::Vector3d velocity_end = true_velocity(backend);
    const RobotState& state = loop.tick().state;
    error_end = state.position_world - truth_end;
    velocity_error = state.velocity_world - velocity_end;
    height_error_m = state.height_m - truth_end.z();
  }
  bench.counters["pos_err_start_m"] = error_start.norm();
  bench.counters["pos_err_end_m"] = error_end.norm();
  bench.counters["pos_err_end_xy_m"] = error_end.head<2>().norm();
  bench.counters["pos_err_end_z_m"] = error_end.z();
  bench.counters["drift_60s_m"] = (error_end - error_start).norm();
  bench.counters["vel_err_end_m_s"] = velocity_error.norm();
  bench.counters["height_err_end_m"] = height_error_m;
}
BENCHMARK(BM_StandingDrift60s)->Arg(1)->Arg(2)->Arg(3)->ArgName("seed")->Iterations(1)->Unit(benchmark::kMillisecond);

// trot-like inputs: two diagonal feet trusted at a time, noisy kinematics
std::vector<LegObservations> trot_observations(std::size_t count) {
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.005);
  std::vector<LegObservations> all(count);
  for (std::size_t k = 0; k < count; ++k) {
    const bool first_pair = (k / 90) % 2 == 0;
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      LegObservation& obs = all[k][leg];
      const bool diagonal_a = leg == 0 || leg == 3;
      obs.trust = diagonal_a == first_pair ? 1.0 : 0.0;
      obs.foot_relative_world = Eigen::Vector3d(leg < 2 ? 0.16 : -0.16, leg % 2 == 0 ? -0.13 : 0.13, -0.25) +
                                Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
      obs.body_velocity_world = Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
    }
  }
  return all;
}

// one Kalman filter step: predict + correct
void BM_KalmanFilterUpdate(benchmark::State& bench) {
  const std::vector<LegObservations> observations = trot_observations(1024);
  LinearKalmanFilter filter;
  std::array<Eigen::Vector3d, kNumLegs> feet;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) feet[leg] = observations[0][leg].foot_relative_world;
  filter.initialize(Eigen::Vector3d(0, 0, 0.25), Eigen::Vector3d::Zero(), feet);
  std::size_t k = 0;
  for (auto _ : bench) {
    const LegObservations& legs = observations[k++ % observations.size()];
    const LinearKalmanFilter::Trust trust{legs[0].trust, legs[1].trust, legs[2].trust, legs[3].trust};
    filter.predict(Eigen::Vector3d(0.01, 0.0, -0.02), 0.002, trust);
    filter.correct(legs);
    benchmark::DoNotOptimize(filter.state().data());
  }
}
BENCHMARK(BM_KalmanFilterUpdate)->Unit(benchmark::kMicrosecond);

// the whole estimator on a frame: orientation, contacts, kinematics and the filter
void BM_BodyStateEstimatorUpdate(benchmark::State& bench) {
  SensorFrame frame;
  frame.q = robot::whole_body_pose(robot::kStandPose);
  frame.imu_accel = {0.0, 0.0, robot::kGravityMPerS2};
  frame.tau = robot::whole_body_pose({0.0, -2.0, 3.0});
  BodyStateEstimator estimator;
  RobotState state;
  for (auto _ : bench) {
    frame.time_s += 0.002;
    estimator.update(frame, std::nullopt, state);
    benchmark::DoNotOptimize(state.position_world.data());
  }
}
BENCHMARK(BM_BodyStateEstimatorUpdate)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
