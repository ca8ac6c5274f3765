#include "control/locomotion/locomotion_controller.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "control/locomotion/swing_trajectory.hpp"
#include "control/leg_gravity.hpp"
#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"
#include "safety/body_watch.hpp"

namespace cerebellum {
namespace {

double wrap_angle(double a) { return std::remainder(a, 2.0 * robot::kPi); }

// the turn rate at speed, lowered until |v| |yaw rate| is within the centripetal acceleration
// the feet can carry
void limit_turn_at_speed(Eigen::Vector3d& velocity, double max_centripetal_accel_m_s2) {
  const double speed = velocity.head<2>().norm();
  if (speed * std::abs(velocity.z()) > max_centripetal_accel_m_s2)
    velocity.z() = std::copysign(max_centripetal_accel_m_s2 / speed, velocity.z());
}

double approach(double current, double target, double max_step) {
  return current + std::clamp(target - current, -max_step, max_step);
}

Eigen::Matrix3d yaw_rotation(double yaw) { return Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }

// where a foot's centre is in the world, on the estimate
Eigen::Vector3d foot_in_world(const RobotState& state, const Eigen::Matrix3d& body_to_world, std::size_t leg) {
  return state.position_world + body_to_world * state.foot_position_body[leg];
}

}  // namespace

LocomotionController::LocomotionController(const LocomotionConfig& config, std::unique_ptr<qp::QpSolver> solver)
    : config_(config),
      mpc_(config_.mpc, std::move(solver)),
      worker_(mpc_),
      scheduler_(config.tick_s * config.ticks_per_segment),
      slip_watch_(config.slip_watch) {
  target_.gait = *gait_pattern(kStandGaitId);
  target_.height_m = config.default_height_m;
  target_.step_height_front_m = target_.step_height_rear_m = find_gait(kStandGaitId)->default_step_height_m;
}

void LocomotionController::reset(const RobotState& state) {
  scheduler_ = GaitScheduler(config_.tick_s * config_.ticks_per_segment);
  scheduler_.set_pattern(target_.gait);
  gait_change_pending_ = false;
  bridging_ = false;
  velocity_.setZero();
  velocity_before_.setZero();
  yaw_des_ = state.rpy.z();
  position_des_ = state.position_world.head<2>();
  velocity_trim_.setZero();
  touched_early_.fill(false);
  touching_ticks_.fill(0);
  reaching_.fill(false);
  height_correction_m_ = 0.0;
  tick_in_segment_ = 0;
  was_stance_.fill(true);
  swing_frame_ = state.orientation.toRotationMatrix();
  in_flight_ = false;
  // until the first solution: share the weight evenly
  const double share = config_.mpc.mass_kg * robot::kGravityMPerS2 / kNumLegs;
  for (auto& f : forces_) f = Eigen::Vector3d(0.0, 0.0, share);
  MpcOutput stale;
  worker_.take(stale);
  consecutive_failures_ = 0;
}

bool LocomotionController::set_command(const LocomotionTarget& command) {
  if (!command.velocity.allFinite() || !std::isfinite(command.height_m) || !std::isfinite(command.pitch_rad) ||
      !std::isfinite(command.step_height_front_m) || !std::isfinite(command.step_height_rear_m)) {
    return false;
  }
  const bool new_gait = command.gait.id != target_.gait.id ||
                        command.gait.period_segments != target_.gait.period_segments ||
                        command.gait.stance != target_.gait.stance;
  target_ = command;
  for (int axis = 0; axis < 3; ++axis) {
    // a stand gait allows no velocity: the gait still stepping while it waits brings the body to rest
    target_.velocity[axis] =
        std::clamp(command.velocity[axis], command.gait.velocity_min[axis], command.gait.velocity_max[axis]);
  }
  limit_turn_at_speed(target_.velocity, config_.max_centripetal_accel_m_s2);
  if (new_gait) {
    pending_gait_ = command.gait;
    gait_change_pending_ = true;
  }
  return true;
}

ContactSchedule LocomotionController::contact_schedule() const {
  ContactSchedule schedule{};
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const LegPhase phase = scheduler_.leg_phase(leg);
    schedule[leg] = {phase.stance && !reaching_[leg] ? 1.0 : 0.0, phase.stance_phase};
  }
  return schedule;
}

void LocomotionController::ramp_velocity() {
  Eigen::Vector3d goal = target_.velocity;
  // while a new gait waits for the running one's cycle to end, the running gait is driven within
  // its own limits only: a bound turned at the variable trot's 2.5 rad/s through its last cycle
  // handed the trot feet swept under the body (and fell)
  const GaitPattern& running = scheduler_.pattern();
  if (gait_change_pending_ && !bridging_ && !scheduler_.playing() && steps(running)) {
    for (int axis = 0; axis < 3; ++axis) {
      goal[axis] = std::clamp(goal[axis], running.velocity_min[axis], running.velocity_max[axis]);
    }
  }
  // on a slippery ground (slip_response) the feet carry less: gentler ramps, wider turns
  const bool slippery = responding_to_slip();
  const double ramp_share = slippery ? config_.slippery_ramp_share : 1.0;
  if (slippery) limit_turn_at_speed(goal, config_.slippery_centripetal_accel_m_s2);
  const double dv = config_.max_accel_m_s2 * ramp_share * config_.tick_s;
  velocity_.x() = approach(velocity_.x(), goal.x(), dv);
  velocity_.y() = approach(velocity_.y(), goal.y(), dv);
  velocity_.z() = approach(velocity_.z(), goal.z(), config_.max_yaw_accel_rad_s2 * ramp_share * config_.tick_s);
  velocity_before_ +=
      (velocity_ - velocity_before_) * std::min(1.0, config_.tick_s / config_.push_reference_time_constant_s);
}

void LocomotionController::update_velocity_trim(const RobotState& state) {
  if (config_.velocity_trim_gain_per_s <= 0.0 || !steps(scheduler_.pattern()) || scheduler_.playing()) {
    // no drag to learn standing or on a user gait's own steps
    velocity_trim_.setZero();
    return;
  }
  const Eigen::Vector2d error = velocity_.head<2>() - state.velocity_body.head<2>();
  // a push is no drag: the trim is kept through it, not wound up by it
  const bool learning = error.norm() <= config_.velocity_trim_error_window_m_s;
  for (int axis = 0; axis < 2; ++axis) {
    const double limit = config_.velocity_trim_max_fraction * std::abs(velocity_[axis]);
    const double step = learning ? config_.velocity_trim_gain_per_s * error[axis] * config_.tick_s : 0.0;
    velocity_trim_[axis] = std::clamp(velocity_trim_[axis] + step, -limit, limit);
  }
}

Eigen::Vector3d LocomotionController::hip_on_ground_world(std::size_t leg, const RobotState& state, double ahead_s,
                                                          double yaw_ahead_s) const {
  const double half_width = target_.vertical_legs ? config_.vertical_leg_half_width_m : config_.pigeon_toe_half_width_m;
  const Eigen::Vector3d hip_body(is_front_leg(leg) ? robot::kHipX : -robot::kHipX, leg_side_sign(leg) * half_width,
                                 0.0);
  const double yaw_ahead = state.rpy.z() + velocity_.z() * yaw_ahead_s;
  const Eigen::Vector3d velocity_world = yaw_rotation(state.rpy.z()) * Eigen::Vector3d(velocity_.x(), velocity_.y(), 0);
  Eigen::Vector3d hip = state.position_world + yaw_rotation(yaw_ahead) * hip_body + velocity_world * ahead_s;
  hip.z() = state.ground.height_at(hip.x(), hip.y());  // the ground plane under the hip
  return hip;
}

void LocomotionController::post_mpc(const RobotState& state) {
  const double dt = config_.mpc.dt_s;
  MpcInput& in = mpc_input_;
  in.x0 << state.rpy, state.position_world, state.omega_world, state.velocity_world, -robot::kGravityMPerS2;
  // yaw without wrap: the reference continues from the current yaw
  const double yaw = state.rpy.z();
  const UserStepTargets no_user_step;
  const UserStepTargets& user = target_.user_step ? *target_.user_step : no_user_step;
  const double yaw_offset = std::clamp(wrap_angle(yaw_des_ + user.yaw_offset_rad - yaw), -0.2, 0.2);
  const double pitch_ref = target_.pitch_rad + state.ground.pitch_along(yaw);
  const double roll_ref = user.roll_rad + state.ground.roll_along(yaw);
  in.contact = scheduler_.horizon_contacts<kMpcHorizon>();
  // a foot still reaching for the ground carries nothing in this segment
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    if (reaching_[leg]) in.contact[0][leg] = false;
  }
  const Eigen::Matrix3d body_to_world = state.orientation.toRotationMatrix();
  // a stand that leans instead of stepping holds the centre of mass over the middle of its feet,
  // not where the trunk was when the stand began, and holds it there firmly; a user step that
  // moves the body by position holds it as firmly where its reference goes
  Eigen::Vector2d start_xy = position_des_;
  in.hold_position = (target_.stand_holds_position || user.leans_to_position) && stands_throughout(in.contact);
  if (in.hold_position && !user.leans_to_position) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& foot : state.foot_position_body) centroid += 0.25 * foot;
    // the robot's own centre (as the QP stand and the jumps place it), not the MPC's tuned offset
    start_xy = state.position_world.head<2>() + (body_to_world * (centroid - stand_com_body_)).head<2>();
  }
  // the reference turns with the commanded yaw rate: velocity and position follow the arc
  const Eigen::Vector3d start(start_xy.x(), start_xy.y(), state.position_world.z());
  Eigen::Vector3d position = start;
  for (int k = 0; k < kMpcHorizon; ++k) {
    const double yaw_k = yaw + yaw_offset + velocity_.z() * (k + 1) * dt;
    const Eigen::Vector3d velocity_world =
        yaw_rotation(yaw_k) * Eigen::Vector3d(velocity_.x() + velocity_trim_.x(), velocity_.y() + velocity_trim_.y(), 0.0);
    in.com_shift[k] = position - start;
    position += velocity_world * dt;
    auto& x = in.x_ref[k];
    const double ground_z = state.ground.height_at(position.x(), position.y());
    x << roll_ref, pitch_ref, yaw_k, position.x(), position.y(), ground_z + target_.height_m + height_correction_m_,
        0.0, 0.0, velocity_.z(), velocity_world.x(), velocity_world.y(), 0.0, -robot::kGravityMPerS2;
  }
  const Eigen::Vector3d lever_origin_world = state.position_world + body_to_world * config_.mpc_lever_arm_origin_body;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    // a foot in the air pushes next from where it will land
    const LegPhase phase = scheduler_.leg_phase(leg);
    in.foot_from_com[leg] =
        phase.stance
            ? Eigen::Vector3d(body_to_world * (state.foot_position_body[leg] - config_.mpc_lever_arm_origin_body))
            : Eigen::Vector3d(foothold_world(leg, phase, state) - lever_origin_world);
  }
  in.friction = user.friction;
  if (responding_to_slip()) in.pyramid = FrictionPyramid::Diamond;
  worker_.post(in);
}

void LocomotionController::collect_mpc() {
  if (!worker_.take(mpc_output_)) return;
  ++telemetry_.mpc_solves;
  telemetry_.last_status = mpc_output_.status;
  telemetry_.last_variables = mpc_output_.variables;
  if (mpc_output_.status != qp::QpStatus::Solved) {
    ++telemetry_.mpc_failures;
    ++consecutive_failures_;
    return;  // keep the previous forces for this segment
  }
  consecutive_failures_ = 0;
  forces_ = mpc_output_.forces;
}

void LocomotionController::observe_slip(std::size_t leg, const LegPhase& phase, const RobotState& state,
                                        const Eigen::Matrix3d& body_to_world) {
  // a foot that reaches for a lower ground is moving on purpose
  const bool planted = phase.stance && !reaching_[leg];
  double speed_m_s = 0.0;
  if (planted) {
    // the contact point's velocity: the trunk's estimate less what it would be were the foot
    // rolling without slipping (a foot's centre moves as its sphere rolls: 0.1 m/s at a shank
    // turning 5 rad/s, as much as a slip)
    const Eigen::Vector3d contact_velocity_world =
        state.velocity_world - trunk_velocity_over_rolling_foot(leg, body_to_world, state.omega_body,
                                                                leg_vector(state.q, leg), leg_vector(state.qd, leg));
    speed_m_s = contact_velocity_world.head<2>().norm();
  }
  slip_watch_.observe(leg, planted, phase.stance_phase, speed_m_s);
}

void LocomotionController::command_stance_leg(std::size_t leg, const RobotState& state, JointCommand& command) {
  const Eigen::Vector3d q = leg_vector(state.q, leg);
  const Eigen::Matrix3d jacobian = foot_jacobian(leg, q);
  const Eigen::Matrix3d world_to_body = state.orientation.toRotationMatrix().transpose();
  // the ground's force f on the foot needs joint torques tau = -J^T f (body frame)
  // standing (a stand pattern: no leg steps), plus what holds the leg's own links against
  // gravity: without it the leg's weight leaves a sideways force on each standing foot, the soft
  // contact lets the feet creep inward about 5 mm/s and 11/31 tipped over after about 17 s.
  // Stepping gaits re-place their feet every cycle and were tuned without it (with it, the 15 N s
  // push recovery and the two-beat user trot fell): re-tuning them is open work
  Eigen::Vector3d tau = -jacobian.transpose() * (world_to_body * forces_[leg]);
  if (!steps(scheduler_.pattern()) && !bridging_ && !scheduler_.playing()) {
    tau += leg_gravity_torque(leg, q, world_to_body * Eigen::Vector3d(0.0, 0.0, -robot::kGravityMPerS2));
  }
  // joint damping toward a foot at rest in the world
  const Eigen::Vector3d foot_velocity_body =
      -(world_to_body * state.velocity_world + state.omega_body.cross(state.foot_position_body[leg]));
  Eigen::Vector3d qd_des = Eigen::Vector3d::Zero();
  if (std::abs(jacobian.determinant()) > 1e-6) qd_des = jacobian.inverse() * foot_velocity_body;
  for (int j = 0; j < 3; ++j) {
    const std::size_t i = 3 * leg + j;
    command.q_des[i] = state.q[i];
    command.qd_des[i] = qd_des[j];
    command.kp[i] = 0.0;
    command.kd[i] = responding_to_slip() ? config_.slippery_stance_kd : config_.stance_kd;
    command.tau_ff[i] = tau[j];
  }
}

Eigen::Vector3d LocomotionController::foothold_world(std::size_t leg, const LegPhase& phase,
                                                     const RobotState& state) const {
  const double remaining_s = (1.0 - phase.swing_phase) * phase.swing_duration_s;
  if (target_.user_step) {
    // a user gait names the landing point: from under the hip at touchdown, corrected by the
    // velocity error times the step's landing gain
    const UserStepTargets& step = *target_.user_step;
    const Eigen::Vector3d hip = hip_on_ground_world(leg, state, remaining_s, remaining_s);
    const double yaw_touchdown = state.rpy.z() + velocity_.z() * remaining_s;
    const Eigen::Vector2d offset = Eigen::Rotation2Dd(yaw_touchdown) * step.landing_offset_m[leg];
    const Eigen::Vector3d velocity_des_world =
        yaw_rotation(state.rpy.z()) * Eigen::Vector3d(velocity_.x(), velocity_.y(), 0.0);
    Eigen::Vector2d feedback =
        step.landing_gain * config_.foothold.velocity_gain * (state.velocity_world - velocity_des_world).head<2>();
    const double reach = config_.foothold.max_offset_forward_m;
    feedback = feedback.cwiseMax(-reach).cwiseMin(reach);
    Eigen::Vector3d foothold = hip;
    foothold.head<2>() += offset + feedback;
    foothold.z() = state.ground.height_at(foothold.x(), foothold.y()) + robot::kFootRadius;
    return foothold;
  }
  // the hip where the body will be at touchdown, turned on by half the stance so that the
  // foot is under the hip in the middle of its stance
  const Eigen::Vector3d hip = hip_on_ground_world(leg, state, remaining_s, remaining_s + 0.5 * phase.stance_duration_s);
  const Eigen::Matrix3d heading = yaw_rotation(state.rpy.z());
  const Eigen::Vector3d velocity_des_world = heading * Eigen::Vector3d(velocity_.x(), velocity_.y(), 0.0);
  const Eigen::Vector3d velocity_before_world =
      heading * Eigen::Vector3d(velocity_before_.x(), velocity_before_.y(), 0.0);
  Eigen::Vector3d foothold = raibert_foothold(hip, state.velocity_world, velocity_des_world, velocity_before_world,
                                              velocity_.z(), state.rpy.z(), phase.stance_duration_s, target_.height_m,
                                              config_.foothold, target_.catching_push);
  if (config_.foothold_on_own_ground) {
    const Eigen::Vector3d& from = swing_start_[leg];  // the foot's centre where this swing began
    foothold.z() = from.z() - robot::kFootRadius + state.ground.height_at(foothold.x(), foothold.y()) -
                   state.ground.height_at(from.x(), from.y());
  }
  foothold.z() += robot::kFootRadius;  // foot centre above the ground
  return foothold;
}

void LocomotionController::command_swing_leg(std::size_t leg, const LegPhase& phase, const RobotState& state,
                                             JointCommand& command) {
  const Eigen::Vector3d foothold = foothold_world(leg, phase, state);
  // in a hop the body's own rise clears the ground: lifting the feet the full step height in the
  // air swings the legs hard enough to pitch the body
  const double lift =
      !scheduler_.playing() && legs_swing_together(scheduler_.pattern()) ? config_.hop_step_height_fraction : 1.0;
  const double height = target_.user_step
                            ? target_.user_step->step_height_m[leg]
                            : lift * (is_front_leg(leg) ? target_.step_height_front_m : target_.step_height_rear_m);
  SwingPoint point =
      swing_point(swing_start_[leg], foothold, height, phase.swing_phase, std::max(phase.swing_duration_s, 1e-3));
  if (!touched_early_[leg] && config_.early_touchdown_force_n > 0.0) {
    const Eigen::Vector3d foot_world = foot_in_world(state, state.orientation.toRotationMatrix(), leg);
    const bool touching = phase.swing_phase > config_.early_touchdown_from_phase &&
                          foot_world.z() - point.position.z() > config_.early_touchdown_above_path_m &&
                          ground_pushes_back(leg, state);
    touching_ticks_[leg] = touching ? touching_ticks_[leg] + 1 : 0;
    if (touching_ticks_[leg] >= config_.early_touchdown_ticks) {
      touched_early_[leg] = true;
      early_touchdown_world_[leg] = foot_world;
    }
  }
  if (touched_early_[leg]) {
    // stays on what it met until its stance begins
    point.position = early_touchdown_world_[leg];
    point.velocity.setZero();
  }
  track_foot_point(leg, point, state, command);
}

void LocomotionController::track_foot_point(std::size_t leg, const SwingPoint& point, const RobotState& state,
                                            JointCommand& command) const {
  // in flight the legs follow their targets in the attitude of the takeoff: tracking world targets
  // from a rolling body would swing the legs against the roll and spin the body further
  const Eigen::Matrix3d world_to_body = swing_frame_.transpose();
  // inside the interface's foot workspace with a margin: a foothold chasing a push, seen from a
  // pitched or rolled trunk, otherwise crosses its edge and the footpos watch damps a robot that
  // was recovering (most falls of the 0.5 s push sweep)
  const Eigen::Vector3d p_body = clamp_into_foot_workspace(leg, world_to_body * (point.position - state.position_world),
                                                           FootWorkspace{}, config_.workspace_margin_m);
  Eigen::Vector3d v_body = world_to_body * (point.velocity - state.velocity_world);
  if (!in_flight_) v_body -= state.omega_body.cross(p_body);
  const LegIkResult ik = inverse_kinematics_in_body(leg, p_body);
  const Eigen::Matrix3d jacobian = foot_jacobian(leg, ik.q);
  Eigen::Vector3d qd_des = Eigen::Vector3d::Zero();
  if (std::abs(jacobian.determinant()) > 1e-6) qd_des = jacobian.inverse() * v_body;
  for (int j = 0; j < 3; ++j) {
    const std::size_t i = 3 * leg + j;
    command.q_des[i] = ik.q[j];
    command.qd_des[i] = qd_des[j];
    command.kp[i] = config_.swing_kp;
    command.kd[i] = config_.swing_kd;
    command.tau_ff[i] = 0.0;
  }
}

bool LocomotionController::ground_pushes_back(std::size_t leg, const RobotState& state) const {
  return ground_force_on_foot_world(state, leg).z() > config_.early_touchdown_force_n;
}

void LocomotionController::command_reaching_leg(std::size_t leg, const RobotState& state, JointCommand& command) {
  reach_elapsed_s_[leg] += config_.tick_s;
  touching_ticks_[leg] = ground_pushes_back(leg, state) ? touching_ticks_[leg] + 1 : 0;
  const double depth = config_.late_touchdown_reach_speed_m_s * reach_elapsed_s_[leg];
  if (touching_ticks_[leg] >= config_.late_touchdown_ticks || depth > config_.late_touchdown_reach_m) {
    // on the ground (or as deep as a blind foot looks): the stance takes it from the next tick
    reaching_[leg] = false;
    touching_ticks_[leg] = 0;
  }
  SwingPoint point;
  point.position = reach_from_world_[leg] - Eigen::Vector3d(0.0, 0.0, std::min(depth, config_.late_touchdown_reach_m));
  point.velocity = Eigen::Vector3d(0.0, 0.0, -config_.late_touchdown_reach_speed_m_s);
  track_foot_point(leg, point, state, command);
}

void LocomotionController::change_pattern_if_due(const RobotState& state) {
  GaitPattern next = scheduler_.pattern();
  const bool leaving_bridge = bridging_;
  // the first `axes` of a velocity within the new gait's limits widened by a margin
  const auto within = [&](const Eigen::Vector3d& velocity, int axes, double margin) {
    for (int axis = 0; axis < axes; ++axis) {
      if (velocity[axis] < pending_gait_.velocity_min[axis] - margin ||
          velocity[axis] > pending_gait_.velocity_max[axis] + margin) {
        return false;
      }
    }
    return true;
  };
  // a gait takes over only at a speed it can step at: the current one slows the body down to the
  // new gait's limits first (a stand gait cannot stop a moving body at all), the ramped command and
  // the body itself, which the new gait must carry: the ramped command
  // reaches the new limits long before a fast body does (a flying trot sliding sideways at 0.7 m/s
  // handed over to the slow trot, whose 0.2 m/s sideways could not hold it, fell in the soak)
  const bool within_limits =
      within(velocity_, 3, config_.gait_switch_velocity_margin) &&
      (!steps(pending_gait_) || within(state.velocity_body, 2, config_.gait_switch_body_margin_m_s));
  const bool to_stand = !steps(pending_gait_);
  const bool moving = state.velocity_world.head<2>().norm() > 0.15;
  const bool ready = gait_change_pending_ && within_limits && !(to_stand && moving);
  if (bridging_) {
    // the bridge ends with its cycle: into the new gait, or back to the old one when a newer
    // command is not ready for its gait yet
    next = ready ? pending_gait_ : gait_before_bridge_;
    if (ready) gait_change_pending_ = false;
    bridging_ = false;
  } else if (ready && config_.gait_bridge_segments > 0 && steps(next) && steps(pending_gait_) &&
             next.id != pending_gait_.id) {
    gait_before_bridge_ = next;
    next = stand_bridge_pattern(stands_on_lone_pairs(next) ? config_.lone_pair_exit_bridge_segments
                                                           : config_.gait_bridge_segments);
    bridging_ = true;
  } else if (ready) {
    next = pending_gait_;
    gait_change_pending_ = false;
    // a stand holds the trunk where it came to rest, not where the commanded velocity would have
    // taken it: the lag the walk left behind (up to max_position_lag_m) is not walked off on
    // planted feet
    if (to_stand) {
      position_des_ = state.position_world.head<2>();
      yaw_des_ = state.rpy.z();
    }
  }
  // the variable-frequency trot steps faster as the commanded speed grows (a sideways step reaches
  // about a third as far as a forward one, so lateral speed counts three times; turning counts as
  // the speed of a hip 0.2 m from the centre)
  if (next.adapts_frequency) {
    const auto stride_speed = [](const Eigen::Vector3d& v) {
      return std::hypot(v.x(), 3.0 * v.y()) + 0.2 * std::abs(v.z());
    };
    // the cycle for the faster of the ramped and the commanded speed: the cycle changes only where
    // one begins, and the slowest (0.72 s) kept while the ramp sped the body up to 1 m/s carried
    // its stance feet 0.3 m
    // (the cycle is the table's; the limits stay the commanded pattern's)
    GaitPattern adapted = variable_trot_pattern(std::max(stride_speed(velocity_), stride_speed(target_.velocity)));
    adapted.velocity_min = next.velocity_min;
    adapted.velocity_max = next.velocity_max;
    next = adapted;
  }
  if (next.id == scheduler_.pattern().id && next.period_segments == scheduler_.pattern().period_segments) return;
  if (steps(scheduler_.pattern())) {
    scheduler_.set_pattern(next);
  } else {
    std::array<Eigen::Vector2d, kNumLegs> foot_xy{};
    std::array<double, kNumLegs> foot_y{};
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      foot_xy[leg] = (state.foot_position_body[leg] - stand_com_body_).head<2>();
      foot_y[leg] = foot_xy[leg].y();
    }
    int segment = entry_segment(next, foot_y);
    // out of the bound a trot begins on the diagonal nearer the centre; after other bridges at
    // its cycle's start (choosing there too fell far more in the soak, benchmarks.md)
    if (segment == 0 && leaving_bridge && stands_on_lone_pairs(gait_before_bridge_)) {
      segment = diagonal_entry_segment(next, foot_xy);
    } else if (segment == 0 && !leaving_bridge) {
      segment = sideways_entry_segment(next, state.velocity_body.y(), config_.sideways_entry_speed_m_s);
    }
    scheduler_.restart(next, segment);
  }
  // feet already in the air start their new swing from where they are
  const Eigen::Matrix3d body_to_world = state.orientation.toRotationMatrix();
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    if (!was_stance_[leg]) swing_start_[leg] = foot_in_world(state, body_to_world, leg);
  }
}

void LocomotionController::play(std::shared_ptr<const ContactSequence> sequence, const RobotState& state) {
  scheduler_.play(std::move(sequence));
  gait_change_pending_ = false;
  bridging_ = false;
  tick_in_segment_ = 0;  // the sequence's segments are the MPC's
  // a foot in the air (none from a stand) swings on from where it is
  const Eigen::Matrix3d body_to_world = state.orientation.toRotationMatrix();
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    swing_start_[leg] = foot_in_world(state, body_to_world, leg);
  }
}

void LocomotionController::compute(const RobotState& state, JointCommand& command) {
  ramp_velocity();
  update_velocity_trim(state);
  yaw_des_ = wrap_angle(yaw_des_ + velocity_.z() * config_.tick_s);
  // where the commanded velocity would have taken the trunk, at most a set distance ahead or behind
  // (the MPC's only integral action: leg friction and swing momentum otherwise slow it down)
  position_des_ +=
      (yaw_rotation(state.rpy.z()) * Eigen::Vector3d(velocity_.x(), velocity_.y(), 0.0)).head<2>() * config_.tick_s;
  const Eigen::Vector2d lag = position_des_ - state.position_world.head<2>();
  if (lag.norm() > config_.max_position_lag_m) {
    position_des_ = state.position_world.head<2>() + lag.normalized() * config_.max_position_lag_m;
  }
  height_correction_m_ = std::clamp(
      height_correction_m_ + config_.height_integral_gain * (target_.height_m - state.height_m) * config_.tick_s,
      -config_.height_integral_limit_m, config_.height_integral_limit_m);
  if (tick_in_segment_ == 1) collect_mpc();
  if (tick_in_segment_ == 0) {
    // patterns change only where a cycle starts, so no foot is switched to stance mid-air; a
    // sequence runs to its end first
    const bool sequence_running = scheduler_.playing() && !scheduler_.sequence_finished();
    // a stand (all feet down) leaves for a stepping gait at once, at the new cycle's start:
    // waiting for the stand's own cycle would let a push carry the body up to 0.3 s unstepped
    const bool leaving_stand =
        !bridging_ && !steps(scheduler_.pattern()) && gait_change_pending_ && steps(pending_gait_);
    if ((scheduler_.cycle_phase() < 1e-9 || leaving_stand) && !sequence_running) change_pattern_if_due(state);
    post_mpc(state);
  }
  const Eigen::Matrix3d body_to_world = state.orientation.toRotationMatrix();
  std::array<LegPhase, kNumLegs> phases;
  bool flight = true;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    phases[leg] = scheduler_.leg_phase(leg);
    flight &= !phases[leg].stance;
  }
  if (!flight) swing_frame_ = body_to_world;
  in_flight_ = flight;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const LegPhase& phase = phases[leg];
    if (phase.stance && !was_stance_[leg] && config_.late_touchdown_reach_m > 0.0 &&
        phase.stance_duration_s >= config_.late_touchdown_min_stance_s && !touched_early_[leg] &&
        !ground_pushes_back(leg, state)) {
      // its stance is due and nothing holds the foot up yet (the ground lies lower than planned,
      // off a step): it reaches on down, out of the MPC's stance feet, until it finds the ground
      reaching_[leg] = true;
      reach_elapsed_s_[leg] = 0.0;
      touching_ticks_[leg] = 0;
      reach_from_world_[leg] = foot_in_world(state, body_to_world, leg);
    }
    observe_slip(leg, phase, state, body_to_world);
    if (!phase.stance) reaching_[leg] = false;
    if (reaching_[leg]) {
      command_reaching_leg(leg, state, command);
    } else if (phase.stance) {
      command_stance_leg(leg, state, command);
    } else {
      if (was_stance_[leg]) {
        swing_start_[leg] = foot_in_world(state, body_to_world, leg);
        touched_early_[leg] = false;
        touching_ticks_[leg] = 0;
      }
      command_swing_leg(leg, phase, state, command);
    }
    was_stance_[leg] = phase.stance;
  }
  scheduler_.advance(config_.tick_s);
  tick_in_segment_ = (tick_in_segment_ + 1) % config_.ticks_per_segment;
}

}  // namespace cerebellum
