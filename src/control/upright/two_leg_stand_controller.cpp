#include "control/upright/two_leg_stand_controller.hpp"

#include <algorithm>
#include <cmath>

#include "control/stance_frame.hpp"
#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"
#include "safety/damping_command.hpp"
#include "safety/upright_watch.hpp"

namespace cerebellum {
namespace {

double smoothstep(double x) {
  const double c = std::clamp(x, 0.0, 1.0);
  return c * c * (3.0 - 2.0 * c);
}
double smoothstep_rate(double x) {
  if (x <= 0.0 || x >= 1.0) return 0.0;
  return 6.0 * x * (1.0 - x);
}

}  // namespace

TwoLegStandController::TwoLegStandController(const TwoLegStandConfig& config) : config_(config), stand_(config.stand) {}

TwoLegStandController::~TwoLegStandController() {
  if (pending_.valid()) pending_.wait();
}

bool TwoLegStandController::design_ready(double waited_s) {
  if (!samples_.empty()) return true;
  if (!pending_.valid() || waited_s < config_.design_wait_s) return false;
  try {
    samples_ = pending_.get();
  } catch (const std::exception& error) {
    design_error_ = error.what();
  }
  return !samples_.empty();
}

void TwoLegStandController::start(const RobotState& state, double duration_s) {
  phase_start_s_ = state.time_s;
  heading_yaw_rad_ = state.rpy.z();
  stand_q_ = phase_q_ = state.q;
  // it stands again as high as it stood (within what the QP stand balances)
  stand_height_m_ = std::min(state.height_m, config_.stand.max_height_m);
  // the front feet ahead of the hind feet, level axes: the crouch keeps them where they stand
  const Eigen::Matrix3d tilt = rotation_from_rpy(Eigen::Vector3d(state.rpy.x(), state.rpy.y(), 0.0));
  front_ahead_m_ = 0.5 * (tilt * (state.foot_position_body[0] + state.foot_position_body[1] -
                                  state.foot_position_body[2] - state.foot_position_body[3]))
                             .x();
  const double moves_s = config_.design_wait_s + config_.crouch_s + config_.crouch_settle_s + config_.rise_s +
                         config_.lower_s + config_.front_down_s + config_.restand_s + config_.stand_s;
  hold_s_ = std::max(config_.min_hold_s, std::max(duration_s, config_.reference_duration_s) - moves_s);
  phase_ = TwoLegPhase::Preparing;
  if (samples_.empty() && !pending_.valid() && design_error_.empty()) {
    const TwoLegStandConfig config = config_;
    pending_ = std::async(std::launch::async, [config] {
      return design_upright_balance(config.model_path, config.design, config.control_period_s);
    });
  }
}

void TwoLegStandController::begin_crouch(const RobotState& state) {
  feedback_.setZero();
  phase_ = TwoLegPhase::Crouch;
  phase_start_s_ = state.time_s;
  last_elapsed_s_ = 0.0;
  phase_q_ = state.q;
  // s = 0's joints, the front feet put on their spots (level distance front_ahead_m_ from the
  // hind feet) from s = 0's trunk
  const UprightSample& crouch = samples_.front();
  for (std::size_t j = 0; j < kNumJoints; ++j) crouch_q_[j] = crouch.position[7 + j];
  const Eigen::Matrix3d r = upright_orientation(crouch.position).toRotationMatrix();
  for (std::size_t leg = 0; leg < 2; ++leg) {
    const Vec3 hip_world = crouch.position.head<3>() + r * hip_position(leg);
    const Vec3 stand_foot =
        foot_position_in_body(leg, Vec3(stand_q_[3 * leg], stand_q_[3 * leg + 1], stand_q_[3 * leg + 2]));
    Vec3 target(crouch.hind_feet_mid_m.x() + front_ahead_m_, hip_world.y() + (stand_foot.y() - hip_position(leg).y()),
                crouch.hind_feet_mid_m.z() - config_.front_press_m);
    const LegIkResult ik = inverse_kinematics_in_body(leg, r.transpose() * (target - crouch.position.head<3>()));
    for (std::size_t k = 0; k < 3; ++k) crouch_q_[3 * leg + k] = ik.q[k];
  }
}

double TwoLegStandController::total_s() const {
  return config_.design_wait_s + config_.crouch_s + config_.crouch_settle_s + config_.rise_s + hold_s_ +
         config_.lower_s + config_.front_down_s + config_.restand_s + config_.stand_s;
}

double TwoLegStandController::progress() const {
  switch (phase_) {
    case TwoLegPhase::Idle: return 0.0;
    case TwoLegPhase::Standing:
    case TwoLegPhase::Failed: return 1.0;
    default: break;
  }
  // the planned time since the command, below 1 until it stands
  double done = 0.0;
  const TwoLegPhase order[] = {TwoLegPhase::Preparing, TwoLegPhase::Crouch,    TwoLegPhase::Rise,   TwoLegPhase::Hold,
                               TwoLegPhase::Lower,     TwoLegPhase::FrontDown, TwoLegPhase::Restand};
  const double lengths[] = {
      config_.design_wait_s, config_.crouch_s + config_.crouch_settle_s, config_.rise_s, hold_s_, config_.lower_s,
      config_.front_down_s,  config_.restand_s + config_.stand_s};
  for (std::size_t i = 0; i < 7; ++i) {
    if (order[i] == phase_) {
      done += std::min(last_elapsed_s_, lengths[i]);
      break;
    }
    done += lengths[i];
  }
  return std::min(0.99, done / total_s());
}

void TwoLegStandController::joint_ramp(const JointArray<double>& from, const JointArray<double>& to, double share,
                                       JointCommand& command) const {
  const double a = smoothstep(share);
  for (std::size_t j = 0; j < kNumJoints; ++j) {
    command.q_des[j] = from[j] + (to[j] - from[j]) * a;
    command.qd_des[j] = 0.0;
    command.kp[j] = config_.joint_kp;
    command.kd[j] = config_.joint_kd;
    command.tau_ff[j] = 0.0;
  }
}

TwoLegStandController::Bracket TwoLegStandController::bracket(double s) const {
  const double x = std::clamp(s, 0.0, 1.0) * static_cast<double>(samples_.size() - 1);
  const std::size_t i = std::min(samples_.size() - 2, static_cast<std::size_t>(x));
  return {samples_[i], samples_[i + 1], x - static_cast<double>(i)};
}

void TwoLegStandController::reference_at(double s, UprightPosition& position) const {
  const auto [a, b, w] = bracket(s);
  position = a.position + w * (b.position - a.position);
  const Eigen::Quaterniond q = upright_orientation(a.position).slerp(w, upright_orientation(b.position));
  position.segment<4>(3) << q.w(), q.x(), q.y(), q.z();
}

void TwoLegStandController::balance(const RobotState& state, double s, double s_rate_per_s, JointCommand& command) {
  const auto [a, b, w] = bracket(s);
  reference_at(s, reference_);
  // the reference's velocity: the family's tangent times the rate of progress
  const double ds = 1e-3;
  reference_at(s + ds, reference_next_);
  const UprightVelocity reference_velocity =
      upright_difference(reference_, reference_next_) * (s_rate_per_s / ds) * (s + ds <= 1.0 ? 1.0 : 0.0);
  const double feet_height_m = a.hind_feet_mid_m.z() + w * (b.hind_feet_mid_m.z() - a.hind_feet_mid_m.z());
  const UprightState now = upright_state(state, heading_yaw_rad_, a.rolling_origin_rad, feet_height_m);
  UprightStateError& error = error_;
  error.head<kUprightVelocitySize>() = upright_difference(reference_, now.position);
  error.tail<kUprightVelocitySize>() = now.velocity - reference_velocity;
  // the trunk's tilt from the reference about the world's horizontal axes (the turn about the
  // vertical is free: friction holds the feet)
  const Eigen::Vector3d tilt_error = upright_orientation(reference_).toRotationMatrix() * error.segment<3>(3);
  if (upright_balance_lost(tilt_error.head<2>().norm(), error.head<3>().norm())) {
    phase_ = TwoLegPhase::Failed;
    command = damping_command(config_.damping_kd, state.q);
    return;
  }
  gain_ = a.gain + w * (b.gain - a.gain);
  const Eigen::Matrix<double, kNumJoints, 1> raw = gain_ * error;
  // the sensors' noise would make the gain chatter at the loop's rate (the battery sags under
  // the drivers' current): a first-order low-pass on the feedback
  const double alpha =
      config_.control_period_s / (config_.control_period_s + 1.0 / (2.0 * robot::kPi * config_.feedback_cutoff_hz));
  feedback_ += alpha * (raw - feedback_);
  const Eigen::Matrix<double, kNumJoints, 1>& torque = feedback_;
  for (std::size_t j = 0; j < kNumJoints; ++j) {
    const double hold = a.torque_nm[j] + w * (b.torque_nm[j] - a.torque_nm[j]);
    command.q_des[j] = state.q[j];
    command.qd_des[j] = reference_velocity[6 + static_cast<Eigen::Index>(j)];
    command.kp[j] = 0.0;
    command.kd[j] = config_.balance_joint_kd;
    command.tau_ff[j] =
        std::clamp(hold - torque[static_cast<Eigen::Index>(j)], -robot::kTorqueMaxNm, robot::kTorqueMaxNm);
  }
}

void TwoLegStandController::compute(const RobotState& state, JointCommand& command) {
  const double t = state.time_s - phase_start_s_;
  last_elapsed_s_ = t;
  const auto next = [&](TwoLegPhase phase) {
    phase_ = phase;
    phase_start_s_ = state.time_s;
    phase_q_ = state.q;
    last_elapsed_s_ = 0.0;
  };
  switch (phase_) {
    case TwoLegPhase::Idle: command = damping_command(config_.damping_kd, state.q); return;
    case TwoLegPhase::Preparing:
      if (design_ready(t)) {
        begin_crouch(state);
        break;
      }
      if (!design_error_.empty()) {
        // no balance to rise with: stay on four feet
        stand_.start(state);
        phase_ = TwoLegPhase::Standing;
        stand_.compute(state, command);
        return;
      }
      joint_ramp(stand_q_, stand_q_, 1.0, command);
      return;
    case TwoLegPhase::Crouch:
      if (t >= config_.crouch_s + config_.crouch_settle_s) {
        next(TwoLegPhase::Rise);
        break;
      }
      joint_ramp(phase_q_, crouch_q_, t / config_.crouch_s, command);
      return;
    case TwoLegPhase::Rise:
      if (t >= config_.rise_s) {
        next(TwoLegPhase::Hold);
        break;
      }
      balance(state, smoothstep(t / config_.rise_s), smoothstep_rate(t / config_.rise_s) / config_.rise_s, command);
      return;
    case TwoLegPhase::Hold:
      if (t >= hold_s_) {
        next(TwoLegPhase::Lower);
        break;
      }
      balance(state, 1.0, 0.0, command);
      return;
    case TwoLegPhase::Lower:
      if (t >= config_.lower_s) {
        next(TwoLegPhase::FrontDown);
        break;
      }
      balance(state, 1.0 - smoothstep(t / config_.lower_s), -smoothstep_rate(t / config_.lower_s) / config_.lower_s,
              command);
      return;
    case TwoLegPhase::FrontDown:
      if (t >= config_.front_down_s) {
        // on four feet again: the QP stand first centres the trunk over them at the crouch's
        // height (rising first would tip it back over the hind feet), then lifts it to the stand
        next(TwoLegPhase::Restand);
        stand_.start(state);
        QpStandGoal centre;
        centre.pose.position = {0.0, 0.0, state.height_m};
        stand_.set_goal(centre, PoseSpeed{1.0, 0.3, 0.5 * config_.restand_s}, 0.5 * config_.restand_s);
        lifting_ = false;
        break;
      }
      joint_ramp(phase_q_, crouch_q_, t / config_.front_down_s, command);
      return;
    case TwoLegPhase::Restand:
      if (t >= config_.restand_s + config_.stand_s) {
        next(TwoLegPhase::Standing);
        break;
      }
      if (!lifting_ && t >= 0.5 * config_.restand_s) {
        lifting_ = true;
        QpStandGoal stand;
        stand.pose.position = {0.0, 0.0, stand_height_m_};
        stand_.set_goal(stand, PoseSpeed{1.0, 0.3, 0.5 * config_.restand_s}, 0.5 * config_.restand_s);
      }
      stand_.compute(state, command);
      return;
    case TwoLegPhase::Standing:
    case TwoLegPhase::Failed: break;
  }
  // phases that changed this tick run their first tick now
  switch (phase_) {
    case TwoLegPhase::Crouch: joint_ramp(phase_q_, crouch_q_, 0.0, command); return;
    case TwoLegPhase::Rise: balance(state, 0.0, 0.0, command); return;
    case TwoLegPhase::Hold: balance(state, 1.0, 0.0, command); return;
    case TwoLegPhase::Lower: balance(state, 1.0, 0.0, command); return;
    case TwoLegPhase::FrontDown: joint_ramp(phase_q_, crouch_q_, 0.0, command); return;
    case TwoLegPhase::Restand: stand_.compute(state, command); return;
    case TwoLegPhase::Standing: stand_.compute(state, command); return;
    default: command = damping_command(config_.damping_kd, state.q); return;
  }
}

}  // namespace cerebellum
