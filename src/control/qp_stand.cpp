#include "control/qp_stand.hpp"

#include <algorithm>

#include "control/pose_reach.hpp"

namespace cerebellum {

QpStand::QpStand(const QpStandConfig& config)
    : config_(config), controller_(config.balance), support_(config.support) {}

void QpStand::start(const RobotState& state) {
  controller_.start(state);
  support_.reset();
  for (Eigen::Vector3d& offset : foot_offsets_) offset.setZero();
  last_time_s_ = state.time_s;
  started_ = true;
  // the current pose in goal terms: offset from the centred stand, height
  const BodyPose& anchored = controller_.frame().anchored_pose();
  const Eigen::Vector2d centred =
      controller_.body_xy_for_com(controller_.frame().centroid(kAllLegs).head<2>(), anchored.rpy);
  BodyPose here = anchored;
  here.position.head<2>() -= centred;
  ramp_.hold(here);
  goal_ = QpStandGoal{};
  goal_.pose = here;
}

void QpStand::set_goal(const QpStandGoal& goal, const PoseSpeed& speed, double min_duration_s) {
  goal_ = goal;
  goal_.pose.position.z() = std::min(goal_.pose.position.z(), config_.max_height_m);
  // a pose the legs cannot hold is cut back towards the level, centred stand at that height
  const StanceFrame& frame = controller_.frame();
  const Eigen::Vector2d com_xy = frame.centroid(kAllLegs).head<2>();
  BodyPose level;
  level.position << controller_.body_xy_for_com(com_xy, level.rpy), goal_.pose.position.z();
  BodyPose wanted = goal_.pose;
  wanted.position.head<2>() += controller_.body_xy_for_com(com_xy, wanted.rpy);
  Footholds footholds{};
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) footholds[leg] = frame.foothold(leg);
  const double fraction = reachable_fraction(level, wanted, footholds, kAllLegs);
  goal_.pose.rpy *= fraction;
  goal_.pose.position.head<2>() *= fraction;
  ramp_.move_to(goal_.pose, std::max(min_duration_s, move_duration_s(ramp_.value(), goal_.pose, speed)));
  if (goal_.lifted_leg >= 0) foot_offsets_[static_cast<std::size_t>(goal_.lifted_leg)] = goal_.lifted_foot_offset;
  support_.request(goal_.lifted_leg);
}

double QpStand::progress() const { return settled() ? 1.0 : std::min({ramp_.fraction(), support_.progress(), 0.99}); }

void QpStand::compute(const RobotState& state, JointCommand& command) {
  const double dt = started_ ? std::max(state.time_s - last_time_s_, 0.0) : 0.0;
  last_time_s_ = state.time_s;
  ramp_.advance(dt);
  support_.advance(dt);

  // centre of mass over the footholds, shifted towards the three that stay down
  const StanceFrame& frame = controller_.frame();
  const BodyPose& pose = ramp_.value();
  Eigen::Vector2d com_xy = frame.centroid(kAllLegs).head<2>();
  BalanceTarget target;
  target.hold_position_xy = goal_.hold_position_xy;
  double offset_scale = 1.0;
  if (const int leg = support_.leg(); leg != SupportSequence::kNoLeg) {
    LegMask support = kAllLegs;
    support[static_cast<std::size_t>(leg)] = false;
    com_xy += support_.shift() * (frame.centroid(support).head<2>() - com_xy);
    // an offset would take the centre of mass off the triangle: fade it while a leg is up
    offset_scale = 1.0 - support_.shift();
    const std::size_t l = static_cast<std::size_t>(leg);
    target.force_z_max_n[l] = support_.load() * config_.balance.distribution.force_z_max_n;
    target.in_air[l] = support_.in_air();
    target.swing_foot[l] = frame.foothold(l) + support_.lift() * foot_offsets_[l];
  }
  target.pose.rpy = pose.rpy;
  target.pose.position.head<2>() =
      controller_.body_xy_for_com(com_xy, pose.rpy) + offset_scale * pose.position.head<2>();
  target.pose.position.z() = pose.position.z();
  target.rate = ramp_.rate();
  controller_.compute(state, target, dt, command);
}

}  // namespace cerebellum
