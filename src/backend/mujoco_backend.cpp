#include "backend/mujoco_backend.hpp"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "backend/terrain_model.hpp"
#include "core/joint_layout.hpp"

namespace cerebellum {
namespace {

int require_id(const mjModel* model, mjtObj type, const std::string& name, const std::string& path) {
  const int id = mj_name2id(model, type, name.c_str());
  if (id < 0) throw std::runtime_error("model " + path + ": missing element '" + name + "'");
  return id;
}

int sensor_address(const mjModel* model, const std::string& name, const std::string& path) {
  return model->sensor_adr[require_id(model, mjOBJ_SENSOR, name, path)];
}

}  // namespace

MujocoBackend::MujocoBackend(const MujocoBackendConfig& config)
    : config_(config),
      terrain_(terrain_geometry(config.terrain)),
      battery_(config.battery),
      main_board_(config.main_board),
      rng_(config.noise.seed) {
  if (!std::filesystem::is_regular_file(config.model_path)) {
    throw std::runtime_error("model file not found: " + config.model_path);
  }
  model_ = load_model_with_terrain(config.model_path, terrain_);
  data_ = mj_makeData(model_);
  // a constructor that throws runs no destructor: free the model here (LeakSanitizer found it)
  try {
    find_model_elements();
    apply_model_error();
    reset_to_start_pose();
  } catch (...) {
    mj_deleteData(data_);
    mj_deleteModel(model_);
    throw;
  }
}

void MujocoBackend::find_model_elements() {
  const MujocoBackendConfig& config = config_;
  // joint and actuator addresses by name, so the model's element order does not matter
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    for (std::size_t j = 0; j < kJointsPerLeg; ++j) {
      const std::string name = std::string(kLegNames[leg]) + "_" + kJointNames[j];
      const std::size_t i = joint_index(leg, j);
      const int joint = require_id(model_, mjOBJ_JOINT, name, config.model_path);
      qpos_address_[i] = model_->jnt_qposadr[joint];
      dof_address_[i] = model_->jnt_dofadr[joint];
      actuator_id_[i] = require_id(model_, mjOBJ_ACTUATOR, name, config.model_path);
    }
  }
  trunk_body_ = require_id(model_, mjOBJ_BODY, "trunk", config.model_path);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    foot_geom_[leg] = require_id(model_, mjOBJ_GEOM, std::string(kLegNames[leg]) + "_foot", config.model_path);
    foot_friction_[leg] = model_->geom_friction[3 * foot_geom_[leg]];
    foot_priority_[leg] = model_->geom_priority[foot_geom_[leg]];
  }
  imu_quat_address_ = sensor_address(model_, "imu_quat", config.model_path);
  imu_gyro_address_ = sensor_address(model_, "imu_gyro", config.model_path);
  imu_accel_address_ = sensor_address(model_, "imu_accel", config.model_path);
}

void MujocoBackend::reset_to_start_pose() {
  const MujocoBackendConfig& config = config_;
  const int key = mj_name2id(model_, mjOBJ_KEY, config.initial_keyframe.c_str());
  if (key < 0) {
    throw std::runtime_error("model " + config.model_path + ": no keyframe '" + config.initial_keyframe +
                             "' (accepted: the <key> names of the model, e.g. lying, stand)");
  }
  mj_resetDataKeyframe(model_, data_, key);
  data_->qpos[2] = config.initial_height_m;
  mj_forward(model_, data_);
  thermal_.assign(kNumJoints, MotorThermalModel(config.thermal));
  bus_voltage_v_ = battery_.reading().voltage_v;
}

MujocoBackend::~MujocoBackend() {
  mj_deleteData(data_);
  mj_deleteModel(model_);
}

SensorFrame MujocoBackend::read() {
  // sensors of the current state (mj_step2 leaves those of the state before integration)
  if (sensors_stale_) {
    mj_forward(model_, data_);
    sensors_stale_ = false;
    forward_is_current_ = true;
  }
  SensorFrame frame;
  frame.time_s = data_->time;
  const SensorNoise& noise = config_.noise;
  auto noisy = [&](double value, double sigma) { return noise.enabled ? value + sigma * unit_normal_(rng_) : value; };
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    frame.q[i] = noisy(data_->qpos[qpos_address_[i]], noise.joint_position_rad);
    frame.qd[i] = noisy(data_->qvel[dof_address_[i]], noise.joint_velocity_rad_s);
    // the driver reports its torque from its current with the data sheet's torque constant
    frame.tau[i] = applied_torque_[i] / config_.model_error.motor_strength_scale;
    frame.temperature_c[i] = thermal_[i].temperature_c();
  }
  frame.motor_faults = motor_faults_;
  frame.driver_mode = driver_mode_;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    frame.motor_faults[i] |= motor_over_speed(data_->qvel[dof_address_[i]]);
  }
  frame.battery = battery_.reading();
  frame.imu_temperature_c = main_board_.temperature_c();
  for (int k = 0; k < 4; ++k) frame.imu_quat[k] = data_->sensordata[imu_quat_address_ + k];
  for (int k = 0; k < 3; ++k) {
    frame.imu_gyro[k] = noisy(data_->sensordata[imu_gyro_address_ + k], noise.gyro_rad_s);
    frame.imu_accel[k] = noisy(data_->sensordata[imu_accel_address_ + k], noise.accel_m_s2);
  }
  return frame;
}

void MujocoBackend::apply_model_error() {
  const ModelError& error = config_.model_error;
  if (!error.any()) return;
  const double mass_kg = model_->body_mass[trunk_body_];
  if (!(mass_kg + error.added_mass_kg > 0.1 * mass_kg)) {
    throw std::runtime_error("model error: " + std::to_string(error.added_mass_kg) + " kg on a trunk of " +
                             std::to_string(mass_kg) + " kg leaves too little of it");
  }
  // a payload spread like the trunk: its inertia grows with its mass
  const double scale = (mass_kg + error.added_mass_kg) / mass_kg;
  model_->body_mass[trunk_body_] = mass_kg + error.added_mass_kg;
  for (int k = 0; k < 3; ++k) {
    model_->body_inertia[3 * trunk_body_ + k] *= scale;
    model_->body_ipos[3 * trunk_body_ + k] += error.com_offset_m[static_cast<std::size_t>(k)];
  }
  if (error.foot_friction > 0.0) {
    // above every ground geom's priority, so the contact takes the foot's friction (MuJoCo otherwise
    // takes the larger of the two)
    int top_priority = 0;
    for (int g = 0; g < model_->ngeom; ++g) top_priority = std::max(top_priority, model_->geom_priority[g]);
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      foot_priority_[leg] = top_priority + 1;
      foot_friction_[leg] = error.foot_friction;
      reset_foot_friction(leg);
    }
  }
  if (!(error.motor_strength_scale > 0.0)) throw std::runtime_error("model error: motor strength must be > 0");
  config_.motor_limits.torque_max_nm *= error.motor_strength_scale;
  if (error.actuation_delay_s < 0.0 || error.actuation_delay_s > kMaxActuationDelayS + 1e-12) {
    throw std::runtime_error("model error: actuation delay must be in [0, 10] ms");
  }
  actuation_delay_s_ = std::round(error.actuation_delay_s / model_->opt.timestep) * model_->opt.timestep;
  // the masses' derived constants (subtree masses, the solver's inverse weights)
  mj_setConst(model_, data_);
}

void MujocoBackend::write(const JointCommand& command) {
  if (actuation_delay_s_ <= 0.0) {
    command_ = command;
    return;
  }
  // fuller than any delay within kMaxActuationDelayS fills it: the oldest reaches the drivers now
  if (pending_count_ == pending_.size()) deliver_oldest_pending_command();
  pending_[(pending_first_ + pending_count_) % pending_.size()] = {data_->time + actuation_delay_s_, command};
  ++pending_count_;
}

void MujocoBackend::deliver_oldest_pending_command() {
  command_ = pending_[pending_first_].command;
  pending_first_ = (pending_first_ + 1) % pending_.size();
  --pending_count_;
}

void MujocoBackend::deliver_pending_commands() {
  while (pending_count_ > 0 && pending_[pending_first_].reaches_drivers_s <= data_->time + 1e-9) {
    deliver_oldest_pending_command();
  }
}

void MujocoBackend::apply_motor_drivers() {
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    const double q = data_->qpos[qpos_address_[i]];
    const double qd = data_->qvel[dof_address_[i]];
    // a motor of another strength than the model's gives that much more or less for the same command
    const double requested = config_.model_error.motor_strength_scale *
                             motor_law_torque(command_.q_des[i], command_.qd_des[i], command_.kp[i], command_.kd[i],
                                              command_.tau_ff[i], q, qd);
    // a driver in error has stopped its motor
    const bool driving = std::isfinite(requested) && (motor_faults_[i] & kMotorErrorBits) == 0;
    const double torque = driving ? limit_motor_torque(requested, qd, config_.motor_limits) : 0.0;
    // a driver told nothing (no gain, no torque: the MC's passive command), or stopped on an error,
    // is not in motor mode
    const bool commanded = command_.kp[i] != 0.0 || command_.kd[i] != 0.0 || command_.tau_ff[i] != 0.0;
    driver_mode_[i] = driving && commanded ? MotorDriverMode::Motor : MotorDriverMode::Reset;
    applied_torque_[i] = torque;
    data_->ctrl[actuator_id_[i]] = torque;
  }
}

void MujocoBackend::advance(double period_s) {
  const double dt = model_->opt.timestep;
  const long steps = std::max(1L, std::lround(period_s / dt));
  take_disturbance_requests();
  for (long s = 0; s < steps; ++s) {
    // the drivers and the push evaluate their laws on the state of this physics step
    begin_step(s == 0 && forward_is_current_);
    deliver_pending_commands();
    apply_motor_drivers();
    apply_disturbances();
    mj_step2(model_, data_);
    update_power_and_heat(dt);
  }
  sensors_stale_ = true;
  forward_is_current_ = false;
}

void MujocoBackend::begin_step(bool reuse_forward) {
  // mj_step1 is mj_checkPos, mj_checkVel, then the position and velocity stages, which are
  // functions of qpos, qvel and the model. After read()'s mj_forward on this same state they are
  // in data_ already: recomputing them cost 13 of a tick's 70 us (MuJoCo 2.2.2, this model). Not
  // to the bit: the position stage normalises the trunk's quaternion in qpos, and normalising it a
  // second time moves its last bits now and then (tests/backend/mujoco_backend_step_test.cpp
  // bounds what that adds up to). The checks still run; one that resets a bad state leaves the
  // stages to recompute
  if (!reuse_forward) {
    mj_step1(model_, data_);
    return;
  }
  const int bad_before = data_->warning[mjWARN_BADQPOS].number + data_->warning[mjWARN_BADQVEL].number;
  mj_checkPos(model_, data_);
  mj_checkVel(model_, data_);
  const int bad_after = data_->warning[mjWARN_BADQPOS].number + data_->warning[mjWARN_BADQVEL].number;
  if (bad_after != bad_before) mj_step1(model_, data_);
}

void MujocoBackend::update_power_and_heat(double dt_s) {
  double motor_power_w = 0.0;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    thermal_[i].update(applied_torque_[i], dt_s);
    motor_power_w += motor_electrical_power_w(applied_torque_[i], data_->qvel[dof_address_[i]]);
  }
  battery_.update(motor_power_w, dt_s);
  main_board_.update(config_.battery.idle_power_w, dt_s);
  // the drivers' bus capacitors smooth the pack's voltage before their limits look at it
  bus_voltage_v_ += (battery_.reading().voltage_v - bus_voltage_v_) * std::min(1.0, dt_s / robot::kDriverBusFilterS);
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    motor_faults_[i] = motor_driver_faults(thermal_[i].temperature_c(), bus_voltage_v_, motor_faults_[i]);
  }
}

double MujocoBackend::time_s() const { return data_->time; }

double MujocoBackend::physics_timestep_s() const { return model_->opt.timestep; }

GroundTruth MujocoBackend::ground_truth() const {
  GroundTruth truth;
  for (int k = 0; k < 3; ++k) {
    truth.position[k] = data_->qpos[k];
    truth.velocity_world[k] = data_->qvel[k];
    truth.angular_velocity_body[k] = data_->qvel[3 + k];
  }
  for (int k = 0; k < 4; ++k) truth.quat[k] = data_->qpos[3 + k];
  truth.ground_height_m = ground_height_m(terrain_, truth.position[0], truth.position[1]);
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    truth.q[i] = data_->qpos[qpos_address_[i]];
    truth.qd[i] = data_->qvel[dof_address_[i]];
    truth.tau[i] = applied_torque_[i];
  }
  // robot geoms collide with the world only (the model's contype/conaffinity), so any contact of
  // a foot geom is a foot on the ground or the terrain
  for (int c = 0; c < data_->ncon; ++c) {
    const mjContact& contact = data_->contact[c];
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      if (contact.geom1 != foot_geom_[leg] && contact.geom2 != foot_geom_[leg]) continue;
      truth.foot_contact[leg] = true;
      // the contact force in its frame (normal, two tangents; the frame's rows in world axes):
      // its world z, pointing up on the foot whichever geom MuJoCo names first
      mjtNum force[6];
      mj_contactForce(model_, data_, c, force);
      double z = 0.0;
      for (int k = 0; k < 3; ++k) z += contact.frame[3 * k + 2] * force[k];
      truth.foot_force_z_n[leg] += std::abs(z);
    }
  }
  return truth;
}

void MujocoBackend::set_base_pose(const std::array<double, 3>& position, const std::array<double, 4>& quat) {
  forward_is_current_ = false;
  for (int k = 0; k < 3; ++k) data_->qpos[k] = position[k];
  for (int k = 0; k < 4; ++k) data_->qpos[3 + k] = quat[k];
  mju_normalize4(data_->qpos + 3);
  for (int k = 0; k < 6; ++k) data_->qvel[k] = 0.0;
  mj_forward(model_, data_);
}

void MujocoBackend::set_joint_positions(const JointArray<double>& q) {
  forward_is_current_ = false;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    data_->qpos[qpos_address_[i]] = q[i];
    data_->qvel[dof_address_[i]] = 0.0;
  }
  mj_forward(model_, data_);
}

void MujocoBackend::set_external_force(const std::array<double, 3>& force_n) {
  for (int k = 0; k < 3; ++k) data_->xfrc_applied[6 * trunk_body_ + k] = force_n[k];
}

void MujocoBackend::request_push(const PushRequest& request) {
  std::lock_guard<std::mutex> lock(push_mutex_);
  posted_push_ = request;
}

void MujocoBackend::request_force_pulse(const ForcePulse& pulse) {
  std::lock_guard<std::mutex> lock(push_mutex_);
  posted_pulse_ = pulse;
  ++posted_pulses_;
}

void MujocoBackend::set_foot_friction(std::size_t leg, double friction) {
  forward_is_current_ = false;
  // a contact takes the friction of its higher-priority geom (the larger one between equals)
  const int geom = foot_geom_.at(leg);
  model_->geom_priority[geom] = foot_priority_[leg] + 10;
  model_->geom_friction[3 * geom] = friction;
}

void MujocoBackend::reset_foot_friction(std::size_t leg) {
  forward_is_current_ = false;
  const int geom = foot_geom_.at(leg);
  model_->geom_priority[geom] = foot_priority_[leg];
  model_->geom_friction[3 * geom] = foot_friction_[leg];
}

void MujocoBackend::take_disturbance_requests() {
  // never wait for the poster: a busy mailbox is read at the next advance
  if (!push_mutex_.try_lock()) return;
  push_ = posted_push_;
  if (posted_pulses_ != taken_pulses_) {
    taken_pulses_ = posted_pulses_;
    pulse_ = posted_pulse_;
    pulse_end_s_ = data_->time + pulse_.duration_s;
  }
  push_mutex_.unlock();
}

void MujocoBackend::apply_disturbances() {
  const bool pulse_on = data_->time < pulse_end_s_ - 1e-9;
  // nothing to do without a push or a pulse, and once the force of the last one is lifted
  if (!push_.active && !pushing_ && !pulse_on && !pulsing_) return;
  const double* com = data_->xipos + 3 * trunk_body_;
  const std::array<double, 3> com_world{com[0], com[1], com[2]};
  const std::array<double, 3> velocity_world{data_->qvel[0], data_->qvel[1], data_->qvel[2]};
  std::array<double, 3> force = push_force(push_, com_world, velocity_world, push_spring_);
  if (pulse_on) {
    for (int k = 0; k < 3; ++k) force[k] += pulse_.force_n[k];
  }
  set_external_force(force);
  pushing_ = push_.active;
  pulsing_ = pulse_on;
}

}  // namespace cerebellum
