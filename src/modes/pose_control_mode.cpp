#include "modes/pose_control_mode.hpp"

#include <algorithm>
#include <cmath>

#include "control/balance_controller.hpp"
#include "control/leg_gravity.hpp"
#include "control/pose_reach.hpp"
#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

// gait 5's pose is centred: its x, y offsets are not read
HighLevelCommand centred(const HighLevelCommand& command) {
  HighLevelCommand c = command;
  c.pos_des[0] = c.pos_des[1] = 0.0f;
  return c;
}

}  // namespace

PoseControlMode::PoseControlMode(const PoseControlConfig& config)
    : config_(config), support_(config.support), distribution_(config.distribution), trim_(config.trim) {}

const char* PoseControlMode::check(const HighLevelCommand& command) const {
  switch (command.gait_id) {
    case 0:
    case 3: break;
    case 2:
      if (lifted_leg_from_contact(command.contact) < 0)
        return "mode 21 gait 2 needs one lifted leg in contact (e.g. 0b1110)";
      break;
    case 5:
      if (command.duration <= 0) return "mode 21 gait 5 needs duration > 0";
      break;
    default: return "mode 21 accepts gait 0 (pose), 2 (swing leg), 3 (hold) or 5 (height)";
  }
  if (lifted_leg_from_contact(command.contact) == kInvalidContact)
    return "mode 21 lifts at most one leg (contact bits)";
  return nullptr;
}

void PoseControlMode::enter(const RobotState& state, const HighLevelCommand& command) {
  frame_.anchor(state);
  ramp_.hold(frame_.anchored_pose());
  support_.reset();
  trim_.reset();
  for (Eigen::Vector3d& offset : foot_offsets_) offset.setZero();
  for (Eigen::Vector3d& offset : offsets_now_) offset.setZero();
  pose_.reset(config_.ranges.default_height_m);
  last_time_s_ = state.time_s;
  started_ = true;
  update(state, command);
}

BodyPose PoseControlMode::goal_pose(const HighLevelCommand& command) {
  const PoseControlRanges& r = config_.ranges;
  BodyPose goal;
  goal.rpy = pose_.body_rpy();
  // the stand pose: level, centre of mass over the footholds, at the commanded height
  const Eigen::Vector2d com_xy = frame_.centroid(kAllLegs).head<2>();
  const Eigen::Vector2d stand_xy = com_xy - (rotation_from_rpy(goal.rpy) * config_.com_in_body).head<2>();
  goal.position << stand_xy + pose_.offset_m(), pose_.height_m();
  // rotation about the control point: the body origin swings around it
  const Eigen::Vector3d centre(r.ctrl_point.clamp(command.ctrl_point[0]), r.ctrl_point.clamp(command.ctrl_point[1]),
                               r.ctrl_point.clamp(command.ctrl_point[2]));
  goal.position += centre - rotation_from_rpy(goal.rpy) * centre;
  // a pose the legs cannot hold is cut back towards the level stand at that height
  BodyPose level = goal;
  level.rpy.setZero();
  level.position.head<2>() = com_xy - config_.com_in_body.head<2>();
  Footholds footholds{};
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) footholds[leg] = frame_.foothold(leg);
  return blend(level, goal, reachable_fraction(level, goal, footholds, kAllLegs));
}

void PoseControlMode::update(const RobotState&, const HighLevelCommand& command) {
  gait_ = command.gait_id;
  timed_ = command.duration > 0;
  clamp_note_ = nullptr;
  if (gait_ == kPoseHoldGait) {
    // hold: stop where the body is now; a leg in motion finishes its change
    ramp_.hold(ramp_.value());
    return;
  }
  const bool clamped = command.gait_id == kPoseAbsoluteHeightGait
                           ? pose_.set(centred(command), command.pos_des[2], config_.ranges)
                           : pose_.add(command, command.pos_des[2], config_.ranges);
  clamp_note_ = clamped ? "the pose would leave its range (docs/modes.md, mode 21): held at the range's edge" : nullptr;
  const int leg = lifted_leg_from_contact(command.contact);
  support_.request(leg);
  if (leg >= 0) foot_offsets_[static_cast<std::size_t>(leg)] = lifted_foot_offset(command, leg, config_.foot_offset);
  const BodyPose goal = goal_pose(command);
  const double needed_s = move_duration_s(ramp_.value(), goal, timed_ ? config_.timed_speed : config_.speed);
  ramp_.move_to(goal, timed_ ? std::max(needed_s, command.duration * 1e-3) : needed_s);
}

void PoseControlMode::run(const RobotState& state, JointCommand& command) {
  const double dt = started_ ? std::max(state.time_s - last_time_s_, 0.0) : 0.0;
  last_time_s_ = state.time_s;
  ramp_.advance(dt);
  support_.advance(dt);

  // the body pose to put the joints in: the ramp, plus the weight shift of a leg change
  BodyPose pose = ramp_.value();
  std::array<Eigen::Vector3d, kNumLegs> feet{};
  std::array<double, kNumLegs> force_limit{};
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    feet[leg] = frame_.foothold(leg);
    force_limit[leg] = config_.distribution.force_z_max_n;
  }
  if (const int leg = support_.leg(); leg != SupportSequence::kNoLeg) {
    const std::size_t l = static_cast<std::size_t>(leg);
    LegMask support = kAllLegs;
    support[l] = false;
    pose.position.head<2>() += support_.shift() * (frame_.centroid(support) - frame_.centroid(kAllLegs)).head<2>();
    Eigen::Vector3d step = foot_offsets_[l] - offsets_now_[l];
    const double max_step = config_.lifted_foot_speed_m_s * dt;
    if (step.norm() > max_step) step *= max_step / step.norm();
    offsets_now_[l] += step;
    feet[l] += support_.lift() * offsets_now_[l];
    force_limit[l] = support_.in_air() ? 0.0 : support_.load() * config_.distribution.force_z_max_n;
  }

  // gravity shared among the loaded feet, at the measured posture
  const Eigen::Matrix3d rotation = frame_.body_rotation(state);
  const Eigen::Vector3d com = rotation * config_.com_in_body;
  std::array<Eigen::Vector3d, kNumLegs> feet_from_com{};
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) feet_from_com[leg] = rotation * state.foot_position_body[leg] - com;
  std::array<Eigen::Vector3d, kNumLegs> forces{};
  distribution_.solve(feet_from_com, force_limit, gravity_wrench(config_.mass_kg), forces);

  // joints: inverse kinematics of the feet seen from the commanded body pose
  // the legs are asked for the orientation that makes the IMU read the commanded one
  const Eigen::Matrix3d rotation_des = rotation_from_rpy(trim_.update(pose.rpy, frame_.body_rpy(state), dt));
  const Eigen::Vector3d gravity_body =
      state.orientation.conjugate() * Eigen::Vector3d(0.0, 0.0, -robot::kGravityMPerS2);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const std::size_t j = kJointsPerLeg * leg;
    const LegIkResult ik = inverse_kinematics_in_body(leg, rotation_des.transpose() * (feet[leg] - pose.position));
    const Vec3 q(state.q[j], state.q[j + 1], state.q[j + 2]);
    const Vec3 tau = leg_gravity_torque(leg, q, gravity_body) -
                     foot_jacobian(leg, q).transpose() * (rotation.transpose() * forces[leg]);
    for (std::size_t k = 0; k < kJointsPerLeg; ++k) {
      const Eigen::Index e = static_cast<Eigen::Index>(k);
      command.q_des[j + k] = ik.q[e];
      command.qd_des[j + k] = 0.0;
      command.kp[j + k] = config_.kp;
      command.kd[j + k] = config_.kd;
      command.tau_ff[j + k] = tau[e];
    }
  }
}

int PoseControlMode::progress_percent() const {
  // a timed entry's time runs while it moves (the queue pauses only for unfinished switches)
  if (timed_) return 100;
  if (ramp_.arrived() && support_.settled()) return 100;
  return std::min(static_cast<int>(std::floor(std::min(ramp_.fraction(), support_.progress()) * 100.0)), 99);
}

}  // namespace cerebellum
