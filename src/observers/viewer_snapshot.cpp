#include "observers/viewer_snapshot.hpp"

#include <mujoco/mujoco.h>

#include <Eigen/Geometry>
#include <algorithm>

namespace cerebellum {

SnapshotCapture::SnapshotCapture(const Simulation& simulation)
    : simulation_(simulation), trunk_body_(std::max(0, mj_name2id(simulation.model(), mjOBJ_BODY, "trunk"))) {}

SimSnapshot SnapshotCapture::sized_snapshot() const {
  SimSnapshot snapshot;
  snapshot.qpos.assign(static_cast<std::size_t>(simulation_.model()->nq), 0.0);
  snapshot.qvel.assign(static_cast<std::size_t>(simulation_.model()->nv), 0.0);
  return snapshot;
}

void SnapshotCapture::capture(const CycleRecord& record, SimSnapshot& out) const {
  const mjModel* model = simulation_.model();
  const mjData* data = simulation_.data();
  out.tick = record.tick;
  out.time_s = data->time;
  std::copy_n(data->qpos, std::min(out.qpos.size(), static_cast<std::size_t>(model->nq)), out.qpos.begin());
  std::copy_n(data->qvel, std::min(out.qvel.size(), static_cast<std::size_t>(model->nv)), out.qvel.begin());
  for (int k = 0; k < 3; ++k) out.external_force_n[k] = data->xfrc_applied[6 * trunk_body_ + k];
  out.status = record.high_level.status;
  const HighLevelCommand& running = record.high_level.running_command;
  out.commanded_velocity = {};
  if (running.mode == static_cast<int>(ModeId::Locomotion)) {
    out.commanded_velocity = {running.vel_des[0], running.vel_des[1], running.vel_des[2]};
  }
  const RobotState& state = record.state;
  out.estimated_velocity_body = {state.velocity_body.x(), state.velocity_body.y(), state.omega_body.z()};
  out.estimated_height_m = state.height_m;
  const GroundTruth truth = simulation_.ground_truth();
  out.true_velocity_body = planar_velocity_body(truth.quat, truth.velocity_world, truth.angular_velocity_body);
  out.true_height_m = truth.position[2];
  out.battery_soc_percent = state.battery.present ? state.battery.state_of_charge_percent : -1.0;
  out.battery_v = state.battery.voltage_v;
  const auto hottest = std::max_element(state.temperature_c.begin(), state.temperature_c.end());
  out.hottest_motor = static_cast<int>(hottest - state.temperature_c.begin());
  out.hottest_motor_c = *hottest;
  out.faulty_motors = record.health.faulty_motors;
}

std::array<double, 3> planar_velocity_body(const std::array<double, 4>& quat,
                                           const std::array<double, 3>& velocity_world,
                                           const std::array<double, 3>& angular_velocity_body) {
  const Eigen::Quaterniond body_to_world(quat[0], quat[1], quat[2], quat[3]);
  const Eigen::Vector3d v_body =
      body_to_world.normalized().conjugate() * Eigen::Vector3d(velocity_world[0], velocity_world[1], velocity_world[2]);
  return {v_body.x(), v_body.y(), angular_velocity_body[2]};
}

}  // namespace cerebellum
