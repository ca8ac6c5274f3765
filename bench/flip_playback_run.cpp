#include "flip_playback_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "backend/mujoco_backend.hpp"
#include "core/orientation.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

constexpr double kTickS = 0.002;  // the MC's period: one command per tick, two physics steps
constexpr double kFootFriction = 0.8;
constexpr double kAirborneTrunkHeightM = 0.12;  // the model file's foot friction, perturbed by the seeds

// the trunk's tilt from upright (rad) from its quaternion (w, x, y, z): the body z axis's angle to world z
double tilt_from_upright(const std::array<double, 4>& q) {
  const double body_z_world_z = 1.0 - 2.0 * (q[1] * q[1] + q[2] * q[2]);
  return std::acos(std::clamp(body_z_world_z, -1.0, 1.0));
}

}  // namespace

FlipPlaybackOutcome play_flip_on_simulation(const FlipTrajectory& trajectory, const FlipPlaybackSetup& setup) {
  MujocoBackendConfig config;
  config.model_path = setup.model_path;
  MujocoBackend robot(config);
  std::mt19937_64 random(setup.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const bool perturbed = setup.seed != 0;

  // the plan's start: its stand, feet on the ground
  const FlipSample& start = trajectory.samples.front();
  JointCommand hold = flip_play_command(trajectory, 0.0, setup.gains);
  JointArray<double> q0 = hold.q_des;
  if (perturbed)
    for (double& q : q0) q += 0.03 * unit(random);
  const double pitch0 = start.trunk[2] + (perturbed ? 0.02 * unit(random) : 0.0);
  robot.set_base_pose({start.trunk[0], 0.0, start.trunk[1] + 0.005}, {std::cos(0.5 * pitch0), 0.0, std::sin(0.5 * pitch0), 0.0});
  robot.set_joint_positions(q0);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg)
    robot.set_foot_friction(leg, kFootFriction * (1.0 + (perturbed ? 0.1 * unit(random) : 0.0)));
  for (double t = 0.0; t < setup.settle_s; t += kTickS) {
    robot.write(hold);
    robot.advance(kTickS);
  }

  FlipPlaybackOutcome outcome;
  const GroundTruth before = robot.ground_truth();
  const JointArray<double> temperature_before_c = robot.read().temperature_c;
  const double duration_s = flip_duration_s(trajectory);
  double airborne_s = 0.0;
  for (double t = 0.0; t < duration_s + setup.hold_s; t += kTickS) {
    robot.write(flip_play_command(trajectory, t, setup.gains));
    robot.advance(kTickS);
    const GroundTruth truth = robot.ground_truth();
    outcome.pitch_turned_rad += truth.angular_velocity_body[1] * kTickS;
    if (t < duration_s) outcome.pitch_at_plan_end_rad = outcome.pitch_turned_rad;
    for (std::size_t j = 0; j < kNumJoints; ++j) outcome.peak_torque_nm = std::max(outcome.peak_torque_nm, std::abs(truth.tau[j]));
    outcome.peak_rear_knee_nm = std::max({outcome.peak_rear_knee_nm, std::abs(truth.tau[8]), std::abs(truth.tau[11])});
    // off its feet and not lying on the ground (the trunk's origin above 0.12 m)
    const bool airborne = truth.position[2] > kAirborneTrunkHeightM &&
                          std::none_of(truth.foot_contact.begin(), truth.foot_contact.end(), [](bool c) { return c; });
    airborne_s = airborne ? airborne_s + kTickS : 0.0;
    outcome.flight_s = std::max(outcome.flight_s, airborne_s);
    const long tick = std::lround(t / kTickS);
    if (setup.trace_every_s > 0.0 && tick % std::max(1L, std::lround(setup.trace_every_s / kTickS)) == 0) {
      const FlipSample planned = flip_sample_at(trajectory, t);
      const std::array<double, 4>& q = truth.quat;
      const double roll = rpy_from_quaternion(Eigen::Quaterniond(q[0], q[1], q[2], q[3])).x();
      std::printf("t %.3f phase %d | x %.3f (plan %.3f) z %.3f (plan %.3f) pitch turned %.2f (plan %.2f) roll %.2f | feet %d%d%d%d\n", t,
                  planned.phase, truth.position[0] - before.position[0], planned.trunk[0] - start.trunk[0], truth.position[2],
                  planned.trunk[1], outcome.pitch_turned_rad, planned.trunk[2] - start.trunk[2], roll, truth.foot_contact[0] ? 1 : 0,
                  truth.foot_contact[1] ? 1 : 0, truth.foot_contact[2] ? 1 : 0, truth.foot_contact[3] ? 1 : 0);
    }
  }
  const GroundTruth after = robot.ground_truth();
  const JointArray<double> temperature_after_c = robot.read().temperature_c;
  for (std::size_t j = 0; j < kNumJoints; ++j)
    outcome.temperature_rise_c = std::max(outcome.temperature_rise_c, temperature_after_c[j] - temperature_before_c[j]);
  outcome.landing_distance_m = std::hypot(after.position[0] - before.position[0], after.position[1] - before.position[1]);
  outcome.landed_upright = after.position[2] > 0.15 && tilt_from_upright(after.quat) < 0.5;
  return outcome;
}

}  // namespace cerebellum
