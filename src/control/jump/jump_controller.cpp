#include "control/jump/jump_controller.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "control/leg_gravity.hpp"
#include "control/stand_up_controller.hpp"
#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"
#include "safety/damping_command.hpp"
#include "control/joint_ramp.hpp"

namespace cerebellum {
namespace {

using robot::kGravityMPerS2;

void set_leg(JointCommand& command, std::size_t leg, const Eigen::Vector3d& q, const Eigen::Vector3d& qd, double kp,
             double kd, const Eigen::Vector3d& tau) {
  for (std::size_t k = 0; k < kJointsPerLeg; ++k) {
    const std::size_t j = kJointsPerLeg * leg + k;
    const Eigen::Index e = static_cast<Eigen::Index>(k);
    command.q_des[j] = q[e];
    command.qd_des[j] = qd[e];
    command.kp[j] = kp;
    command.kd[j] = kd;
    command.tau_ff[j] = tau[e];
  }
}


}  // namespace

JumpControllerConfig default_jump_controller_config() {
  JumpControllerConfig config;
  // the landing stand brakes harder than a standing robot is pushed around
  config.stand.balance.max_position_acceleration = config.limits.landing_braking_m_s2;
  return config;
}

const char* jump_phase_name(JumpPhase phase) {
  switch (phase) {
    case JumpPhase::Idle: return "idle";
    case JumpPhase::Crouch: return "crouch";
    case JumpPhase::Push: return "push";
    case JumpPhase::Flight: return "flight";
    case JumpPhase::Landing: return "landing";
    case JumpPhase::Standing: return "standing";
    case JumpPhase::Failed: return "failed";
  }
  return "?";
}

JumpController::JumpController(const JumpControllerConfig& config)
    : config_(config), stand_(config.stand), distribution_(config.push_distribution) {}

void JumpController::start(const RobotState& state, const JumpTarget& target) {
  start(state, plan_jump(target, config_.limits));
}

void JumpController::start(const RobotState& state, const JumpPlan& plan) {
  plan_ = plan;
  phase_ = JumpPhase::Crouch;
  start_s_ = phase_start_s_ = last_time_s_ = state.time_s;
  centred_ = false;
  // the feet land where they stood, seen from the trunk: the stand ends as far from them as it began
  StanceFrame level;
  level.anchor(state);
  const Eigen::Vector3d rpy = level.body_rpy(state);
  const Eigen::Matrix3d tilt = rotation_from_rpy(Eigen::Vector3d(rpy.x(), rpy.y(), 0.0));
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) stand_feet_[leg] = tilt * state.foot_position_body[leg];
  Eigen::Vector3d velocity;
  level.estimate(state, kAllLegs, start_position_, velocity);
  stand_.start(state);
  QpStandGoal crouch;
  crouch.pose.position = {plan_.crouch_offset_m.x(), plan_.crouch_offset_m.y(), plan_.crouch_height_m};
  stand_.set_goal(crouch, PoseSpeed{1.0, 0.5, config_.crouch_duration_s}, config_.crouch_duration_s);
}

void JumpController::hold(const RobotState& state) {
  phase_ = JumpPhase::Standing;
  start_s_ = phase_start_s_ = last_time_s_ = state.time_s;
  stand_.start(state);
}

void JumpController::land(const RobotState& state) {
  start_s_ = last_time_s_ = state.time_s;
  centred_ = false;
  begin_landing(state);
}

double JumpController::progress() const {
  if (phase_ == JumpPhase::Idle) return 0.0;
  if (finished()) return 1.0;
  const double total = config_.crouch_duration_s + config_.crouch_settle_s + plan_.push_duration_s +
                       plan_.flight_duration_s + config_.landing_brake_s + config_.landing_centre_s;
  // the planned time; a late touchdown holds it below 1 until the stand
  return std::min((last_time_s_ - start_s_) / total, 0.99);
}

void JumpController::begin_push(const RobotState& state) {
  phase_ = JumpPhase::Push;
  phase_start_s_ = state.time_s;
  frame_.anchor(state);
  Eigen::Vector3d velocity;
  frame_.estimate(state, kAllLegs, push_origin_, velocity);
  takeoff_velocity_ = plan_.takeoff_velocity_m_s;
  for (Eigen::Vector3d& force : forces_) force.setZero();
}

void JumpController::begin_flight(const RobotState& state) {
  place_landing();
  phase_ = JumpPhase::Flight;
  phase_start_s_ = state.time_s;
  takeoff_q_ = state.q;
}

void JumpController::measure_push_progress(const RobotState& state) {
  // the push's progress, measured while every foot still pushes (near the take-off the legs are
  // nearly straight and leaving the ground: joint rates then give a poor velocity), predicts the
  // take-off: the trunk's velocity as that share of its plan
  const double t = state.time_s - phase_start_s_;
  if (t > config_.push_measured_fraction * plan_.push_duration_s) return;
  Eigen::Vector3d position, velocity;
  frame_.estimate(state, kAllLegs, position, velocity);
  const Eigen::Vector3d planned = plan_.push_acceleration_m_s2 * t;
  const Eigen::Vector2d planned_xy = planned.head<2>();
  takeoff_velocity_ = plan_.takeoff_velocity_m_s;
  if (planned_xy.squaredNorm() > 1e-4) {
    takeoff_velocity_.head<2>() *= velocity.head<2>().dot(planned_xy) / planned_xy.squaredNorm();
  }
  if (planned.z() > 1e-2) takeoff_velocity_.z() *= velocity.z() / planned.z();
}

void JumpController::place_landing() {
  // the centre of mass flies from the planned take-off point with the velocity the push was on
  // course for (it may fall short of its plan: the motors' torque falls with speed) down to the
  // touchdown height
  const Eigen::Vector3d position = push_origin_ + plan_.push_stroke_m;
  const Eigen::Vector3d& velocity = takeoff_velocity_;
  const Eigen::Vector3d com_velocity = plan_.momentum_map * velocity;
  const double touchdown_height_m = plan_.takeoff_height_m + plan_.flight_travel_m.z();
  const double flight_s = flight_time_s(com_velocity.z(), position.z() - touchdown_height_m);
  const Eigen::Vector2d travelled = position.head<2>() + com_velocity.head<2>() * flight_s - start_position_.head<2>();
  // the stand ends centred over the landed feet: they land ahead by what is still to go, and at
  // least by what the landing's braking carries the trunk
  Eigen::Vector2d offset = plan_.planned_displacement_m - travelled;
  const Eigen::Vector2d braking = braking_distance(com_velocity.head<2>(), config_.limits);
  if (braking.norm() > 1e-9) {
    const Eigen::Vector2d along = braking.normalized();
    offset += std::max(braking.norm() - offset.dot(along), 0.0) * along;
  }
  // along the body the leading pair lands further ahead and brakes, the trailing pair less (the
  // centre of mass stays ahead of it); sideways the four land alike
  const double spread_m = config_.landing_spread_fraction * offset.x();
  const double trailing_max_m = config_.landing_trailing_offset_max_m;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const bool leading = (stand_feet_[leg].x() >= 0.0) == (offset.x() >= 0.0);
    landing_offsets_[leg] = offset;
    landing_offsets_[leg].x() += leading ? spread_m : -spread_m;
    if (!leading) landing_offsets_[leg].x() = std::clamp(landing_offsets_[leg].x(), -trailing_max_m, trailing_max_m);
  }
}

void JumpController::begin_landing(const RobotState& state) {
  phase_ = JumpPhase::Landing;
  phase_start_s_ = state.time_s;
  stand_.start(state);
  QpStandGoal brake;
  brake.pose.position = {0.0, 0.0, config_.limits.stand_height_m};
  brake.hold_position_xy = false;
  stand_.set_goal(brake, PoseSpeed{1.0, 0.5, config_.landing_brake_s}, config_.landing_brake_s);
}

void JumpController::compute(const RobotState& state, JointCommand& command) {
  last_time_s_ = state.time_s;
  const double t = state.time_s - phase_start_s_;
  switch (phase_) {
    case JumpPhase::Idle:
    case JumpPhase::Standing: stand_.compute(state, command); return;
    case JumpPhase::Crouch:
      if (t >= config_.crouch_duration_s + config_.crouch_settle_s) {
        begin_push(state);
        push(state, command);
        return;
      }
      stand_.compute(state, command);
      return;
    case JumpPhase::Push:
      if (push_done(state, t)) {
        begin_flight(state);
        fly(state, command);
        return;
      }
      push(state, command);
      return;
    case JumpPhase::Flight:
      if (touched_down(state)) {
        begin_landing(state);
        stand_.compute(state, command);
        return;
      }
      fly(state, command);
      return;
    case JumpPhase::Landing:
      if (landing_failed(state)) {
        phase_ = JumpPhase::Failed;
        break;
      }
      if (!centred_ && t >= config_.landing_brake_s) {
        centred_ = true;
        QpStandGoal centre;
        centre.pose.position = {0.0, 0.0, config_.limits.stand_height_m};
        stand_.set_goal(centre, PoseSpeed{1.0, 0.3, config_.landing_centre_s}, config_.landing_centre_s);
      }
      if (t >= config_.landing_brake_s + config_.landing_centre_s) phase_ = JumpPhase::Standing;
      stand_.compute(state, command);
      return;
    case JumpPhase::Failed: break;
  }
  // failed: the protective stops' joint damping
  command = damping_command(config_.damping_kd);
}

void JumpController::push(const RobotState& state, JointCommand& command) {
  const double t = state.time_s - phase_start_s_;
  const Eigen::Vector3d& a = plan_.push_acceleration_m_s2;
  const Eigen::Vector3d position_des = push_origin_ + 0.5 * a * t * t;
  const Eigen::Vector3d velocity_des = a * t;
  // the trunk's rates ramp up to their take-off values: the turn, and the tilt rates that cancel
  // the legs' angular momentum
  const Eigen::Vector3d takeoff_rate(plan_.takeoff_tilt_rate_rad_s.x(), plan_.takeoff_tilt_rate_rad_s.y(),
                                     plan_.yaw_rate_rad_s);
  const Eigen::Vector3d angular_acceleration_ff = takeoff_rate / plan_.push_duration_s;
  const Eigen::Vector3d rpy_des = 0.5 * angular_acceleration_ff * t * t;
  const Eigen::Vector3d omega_des = angular_acceleration_ff * t;

  Eigen::Vector3d position, velocity;
  frame_.estimate(state, kAllLegs, position, velocity);
  measure_push_progress(state);
  const Eigen::Matrix3d rotation = frame_.body_rotation(state);
  const Eigen::Vector3d omega = frame_.angular_velocity(state);

  const BalanceConfig& body = config_.stand.balance;
  const Eigen::Vector3d acceleration =
      a + config_.push_kp.cwiseProduct(position_des - position) + config_.push_kd.cwiseProduct(velocity_des - velocity);
  const Eigen::Matrix3d rotation_des = rotation_from_rpy(rpy_des);
  const Eigen::Vector3d angle_error = rotation_error(rotation_des, rotation);
  const Eigen::Vector3d angular_acceleration = angular_acceleration_ff +
                                               config_.push_orientation_kp.cwiseProduct(angle_error) +
                                               config_.push_orientation_kd.cwiseProduct(omega_des - omega);
  const Eigen::Matrix3d inertia = rotation * body.inertia_diag.asDiagonal() * rotation.transpose();
  Vector6d wrench;
  // the ground changes the robot's momentum, of which the trunk's acceleration carries K a
  wrench.head<3>() = body.mass_kg * (plan_.momentum_map * acceleration + Eigen::Vector3d(0.0, 0.0, kGravityMPerS2));
  wrench.tail<3>() = inertia * angular_acceleration;

  std::array<double, kNumLegs> force_limit{};
  force_limit.fill(config_.push_distribution.force_z_max_n);
  std::array<Eigen::Vector3d, kNumLegs> solved{};
  if (distribution_.solve(feet_from_com(state, rotation, body.com_in_body), force_limit, wrench, solved) ==
      qp::QpStatus::Solved)
    forces_ = solved;

  const Eigen::Vector3d gravity_body = state.orientation.conjugate() * Eigen::Vector3d(0.0, 0.0, -kGravityMPerS2);
  const Eigen::Matrix3d rotation_des_t = rotation_des.transpose();
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Eigen::Vector3d q = leg_vector(state.q, leg);
    const Eigen::Matrix3d jacobian = foot_jacobian(leg, q);
    const Eigen::Vector3d tau =
        leg_gravity_torque(leg, q, gravity_body) - jacobian.transpose() * (rotation.transpose() * forces_[leg]);
    // the joints follow the planned path too: the foot where it stands, seen from the planned trunk
    const Eigen::Vector3d foot_body = rotation_des_t * (frame_.foothold(leg) - position_des);
    const LegIkResult ik = inverse_kinematics_in_body(leg, foot_body);
    // the foot stands still: its body-frame velocity is -R' v - omega x foot
    const Eigen::Vector3d foot_velocity =
        -rotation_des_t * velocity_des - (rotation_des_t * omega_des).cross(foot_body);
    Eigen::Vector3d qd = Eigen::Vector3d::Zero();
    const Eigen::Matrix3d ik_jacobian = foot_jacobian(leg, ik.q);
    if (std::abs(ik_jacobian.determinant()) > 1e-5) qd = ik_jacobian.inverse() * foot_velocity;
    set_leg(command, leg, ik.q, qd, config_.push_joint_kp, config_.push_joint_kd, tau);
  }
}

bool JumpController::push_done(const RobotState& state, double t) const {
  if (t < plan_.push_duration_s) return false;
  // the motors' torque-speed limit leaves the trunk behind its plan: the push goes on while it is
  // slower than planned and the legs can still extend
  Eigen::Vector3d position, velocity;
  frame_.estimate(state, kAllLegs, position, velocity);
  const Eigen::Vector3d& planned = plan_.takeoff_velocity_m_s;
  const bool fast_enough = velocity.dot(planned) >= config_.takeoff_speed_fraction * planned.squaredNorm();
  // toward the legs' full extension whatever height the plan reaches its speed at (a jump for height)
  const bool legs_extended = position.z() >= config_.limits.takeoff_height_m + config_.push_extra_height_m;
  return fast_enough || legs_extended || t >= config_.push_overrun_fraction * plan_.push_duration_s;
}

void JumpController::fly(const RobotState& state, JointCommand& command) {
  const double t = state.time_s - phase_start_s_;
  const double s = smooth_step(std::clamp(t / config_.swing_duration_s, 0.0, 1.0));
  // the landing pose: each foot where it stood before the jump (relative to the trunk), ahead by
  // its landing offset (place_landing), at the touchdown height below the trunk, whatever the
  // trunk's attitude.
  // The offset is in the take-off heading: it turns back by the yaw since take-off
  const Eigen::Vector3d rpy = frame_.body_rpy(state);
  const Eigen::Matrix3d tilt = rotation_from_rpy(Eigen::Vector3d(rpy.x(), rpy.y(), 0.0));
  const Eigen::Matrix3d unturn = rotation_from_rpy(Eigen::Vector3d(0.0, 0.0, -rpy.z()));
  const Eigen::Vector3d gravity_body = state.orientation.conjugate() * Eigen::Vector3d(0.0, 0.0, -kGravityMPerS2);
  const double leg_m = config_.landing_leg_extension * (robot::kThighLength + robot::kShankLength);
  const double foot_z = -config_.limits.touchdown_height_m + robot::kFootRadius;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Eigen::Vector2d& landing = landing_offsets_[leg];
    Eigen::Vector3d foot = stand_feet_[leg] + unturn * Eigen::Vector3d(landing.x(), landing.y(), 0.0);
    foot.z() = foot_z;
    // a foot beyond the leg's reach lands where the leg, nearly straight, points at it (higher:
    // it touches down later and further on)
    Eigen::Vector3d foot_body = tilt.transpose() * foot;
    const Eigen::Vector3d hip = hip_position(leg);
    const Eigen::Vector2d sagittal(foot_body.x() - hip.x(), foot_body.z() - hip.z());
    if (sagittal.norm() > leg_m) {
      const Eigen::Vector2d reached = sagittal * (leg_m / sagittal.norm());
      foot_body.x() = hip.x() + reached.x();
      foot_body.z() = hip.z() + reached.y();
    }
    const LegIkResult ik = inverse_kinematics_in_body(leg, foot_body);
    const Eigen::Vector3d from = leg_vector(takeoff_q_, leg);
    const Eigen::Vector3d q = from + (ik.q - from) * s;
    const Eigen::Vector3d tau = leg_gravity_torque(leg, leg_vector(state.q, leg), gravity_body);
    set_leg(command, leg, q, Eigen::Vector3d::Zero(), config_.flight_joint_kp, config_.flight_joint_kd, tau);
  }
}

bool JumpController::touched_down(const RobotState& state) const {
  const double t = state.time_s - phase_start_s_;
  if (t >= plan_.flight_duration_s + config_.touchdown_latest_extra_s) return true;
  if (t < config_.touchdown_earliest_fraction * plan_.flight_duration_s) return false;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    if (ground_force_on_foot_world(state, leg).z() > config_.touchdown_force_n) return true;
  }
  return false;
}

bool JumpController::landing_failed(const RobotState& state) const {
  const bool tipped = std::max(std::abs(state.rpy.x()), std::abs(state.rpy.y())) > config_.failed_tilt_rad;
  const bool sunk = stand_.controller().estimated_pose().position.z() < config_.failed_height_m;
  return tipped || sunk;
}

}  // namespace cerebellum
