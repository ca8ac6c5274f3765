#include "estimation/body_state_estimator.hpp"

#include <algorithm>
#include <cmath>

#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

// below this total trust no foot says where the ground is
constexpr double kMinGroundTrust = 0.5;

double ramp(double value, double width) { return width > 0.0 ? std::clamp(value / width, 0.0, 1.0) : 1.0; }

}  // namespace

double force_contact_trust(double contact_probability, double time_in_contact_s, double ramp_s) {
  return std::clamp(contact_probability, 0.0, 1.0) * ramp(time_in_contact_s, ramp_s);
}

double scheduled_contact_trust(const LegContactPlan& plan, double ramp_fraction) {
  const double phase = std::clamp(plan.stance_phase, 0.0, 1.0);
  return std::clamp(plan.probability, 0.0, 1.0) * ramp(std::min(phase, 1.0 - phase), ramp_fraction);
}

Eigen::Vector3d trunk_origin_acceleration(const Eigen::Vector3d& imu_accel_world, const Eigen::Matrix3d& body_to_world,
                                          const Eigen::Vector3d& omega_body, const Eigen::Vector3d& alpha_body,
                                          const Eigen::Vector3d& imu_body) {
  return imu_accel_world - body_to_world * (alpha_body.cross(imu_body) + omega_body.cross(omega_body.cross(imu_body)));
}

BodyStateEstimator::BodyStateEstimator(const BodyStateEstimatorConfig& config)
    : config_(config), kinematic_(config.kinematic), filter_(config.filter), ground_(config.ground) {}

void BodyStateEstimator::reset() {
  kinematic_.reset();
  filter_.reset();
  schedule_.reset();
  trust_.fill(0.0);
  time_in_contact_s_.fill(0.0);
  last_time_s_ = 0.0;
  last_omega_body_.setZero();
  ground_z_m_ = 0.0;
}

void BodyStateEstimator::follow_plan(const ContactPlan& plan) {
  if (!plan) {
    schedule_.reset();
    return;
  }
  for (const LegContactPlan& leg : *plan) {
    if (!std::isfinite(leg.probability) || !std::isfinite(leg.stance_phase)) return;
  }
  schedule_ = plan;
}

void BodyStateEstimator::update(const SensorFrame& frame, const ContactPlan& plan, RobotState& state) {
  follow_plan(plan);
  kinematic_.update(frame, plan, state);
  if (!state.valid) {
    if (filter_.initialized()) write_state(state);
    return;
  }
  if (!filter_.initialized()) {
    start_filter(state);
  } else {
    const double dt = std::clamp(frame.time_s - last_time_s_, 0.0, config_.max_step_s);
    update_trust(state, dt);
    // the ground plane: its slope from the planted feet as the legs measure them (trunk estimate +
    // kinematics), its height from the filter's foot states. The filter's feet alone are pulled
    // to the plane by its own ground-height measurement: with the deadband, that loop read a
    // 10-degree ramp too flat for the walking controller to climb it
    LegObservations legs = observe_legs(state);
    std::array<Eigen::Vector3d, kNumLegs> measured_feet;
    std::array<bool, kNumLegs> planted{};
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      measured_feet[leg] = filter_.position() + legs[leg].foot_relative_world;
      planted[leg] = trust_[leg] >= config_.planted_trust;
    }
    ground_.update(measured_feet, filter_feet(), planted, dt);
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      const Eigen::Vector3d foot = filter_.foot_position(leg);
      legs[leg].ground_height_m = ground_.plane().height_at(foot.x(), foot.y());
    }
    const Eigen::Vector3d alpha_body =
        dt > 0.0 ? Eigen::Vector3d((state.omega_body - last_omega_body_) / dt) : Eigen::Vector3d::Zero();
    const Eigen::Vector3d imu_body(robot::kImuPositionBody[0], robot::kImuPositionBody[1], robot::kImuPositionBody[2]);
    const Eigen::Vector3d accel_world = trunk_origin_acceleration(
        state.accel_world, state.orientation.toRotationMatrix(), state.omega_body, alpha_body, imu_body);
    const bool accepted = filter_.predict(accel_world, dt, trust_) && filter_.correct(legs);
    state.valid = accepted;
  }
  last_time_s_ = frame.time_s;
  last_omega_body_ = state.omega_body;
  write_state(state);
}

void BodyStateEstimator::update_trust(const RobotState& state, double dt_s) {
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    time_in_contact_s_[leg] = state.contact[leg] > 0.5 ? time_in_contact_s_[leg] + dt_s : 0.0;
    trust_[leg] = schedule_
                      ? scheduled_contact_trust((*schedule_)[leg], config_.schedule_ramp_fraction)
                      : force_contact_trust(state.contact[leg], time_in_contact_s_[leg], config_.force_contact_ramp_s);
  }
}

void BodyStateEstimator::start_filter(const RobotState& state) {
  // the trunk over the origin at the kinematic height, at rest; feet where the legs put them
  const Eigen::Vector3d position(0.0, 0.0, state.height_m);
  const LegObservations legs = observe_legs(state);
  std::array<Eigen::Vector3d, kNumLegs> feet;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) feet[leg] = position + legs[leg].foot_relative_world;
  filter_.initialize(position, Eigen::Vector3d::Zero(), feet);
  ground_.reset(filter_feet());
  trust_.fill(0.0);
  time_in_contact_s_.fill(0.0);
  ground_z_m_ = 0.0;
}

LegObservations BodyStateEstimator::observe_legs(const RobotState& state) const {
  const Eigen::Matrix3d body_to_world = state.orientation.toRotationMatrix();
  const Eigen::Vector3d foot_radius_up(0.0, 0.0, robot::kFootRadius);
  LegObservations legs;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Vec3 q(state.q[3 * leg], state.q[3 * leg + 1], state.q[3 * leg + 2]);
    const Vec3 qd(state.qd[3 * leg], state.qd[3 * leg + 1], state.qd[3 * leg + 2]);
    const Vec3& foot_body = state.foot_position_body[leg];
    // the filter's foot point is the bottom of the foot sphere: at z = 0 on the ground
    legs[leg].foot_relative_world = body_to_world * foot_body - foot_radius_up;
    // a foot rolling without slip
    legs[leg].body_velocity_world = trunk_velocity_over_rolling_foot(leg, body_to_world, state.omega_body, q, qd);
    legs[leg].trust = trust_[leg];
  }
  return legs;
}

std::array<Eigen::Vector3d, kNumLegs> BodyStateEstimator::filter_feet() const {
  std::array<Eigen::Vector3d, kNumLegs> feet;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) feet[leg] = filter_.foot_position(leg);
  return feet;
}

void BodyStateEstimator::write_state(RobotState& state) {
  state.position_world = filter_.position();
  state.velocity_world = filter_.velocity();
  state.velocity_body = state.orientation.conjugate() * state.velocity_world;
  // ground under the trust-weighted stance feet; through a flight phase, the last such ground
  double trust_sum = 0.0;
  double weighted_foot_z = 0.0;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    trust_sum += trust_[leg];
    weighted_foot_z += trust_[leg] * filter_.foot_position(leg).z();
  }
  if (trust_sum >= kMinGroundTrust) ground_z_m_ = weighted_foot_z / trust_sum;
  state.height_m = state.position_world.z() - ground_z_m_;
  state.ground = ground_.plane();
}

}  // namespace cerebellum
