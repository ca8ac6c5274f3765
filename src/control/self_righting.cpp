#include "control/self_righting.hpp"

#include <algorithm>
#include <cmath>

#include "control/stand_up_controller.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

// leg poses (abad, hip, knee), SDK convention, for a robot on its right side
constexpr std::array<double, 3> kFolded = robot::kLyingPose;
constexpr std::array<double, 3> kOverTheBack{0.0, 2.75, -0.52};      // pointing past the back
constexpr std::array<double, 3> kPushBehindBack{0.68, 2.75, -0.52};   // right leg: foot swung down into the ground
constexpr std::array<double, 3> kReachOut{0.0, 0.0, -0.6};         // straight out on the belly side

}  // namespace

BodyRest body_rest(const Eigen::Quaterniond& body_to_world) {
  const Eigen::Vector3d down = body_to_world.conjugate() * Eigen::Vector3d(0.0, 0.0, -1.0);
  // the trunk counts as upright while it is tilted by less than about 1 rad
  if (down.z() < -std::cos(1.0)) return BodyRest::Upright;
  if (std::abs(down.y()) > std::abs(down.z())) return down.y() < 0.0 ? BodyRest::OnRightSide : BodyRest::OnLeftSide;
  return down.z() > 0.0 ? BodyRest::UpsideDown : BodyRest::Upright;
}

SelfRighting::SelfRighting(const SelfRightingConfig& config) : config_(config) { keyframes_.reserve(8); }

void SelfRighting::add(const std::array<double, 3>& right_legs, const std::array<double, 3>& left_legs, bool mirror,
                       double duration_s) {
  JointKeyframe frame;
  frame.duration_s = duration_s;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const bool right = leg_side_sign(leg) < 0.0;
    // mirrored: the pose meant for the right legs goes to the left legs and the other way round
    const std::array<double, 3>& pose = (right != mirror) ? right_legs : left_legs;
    const double abad_sign = mirror ? -1.0 : 1.0;
    frame.q[kJointsPerLeg * leg] = abad_sign * pose[0];
    frame.q[kJointsPerLeg * leg + 1] = pose[1];
    frame.q[kJointsPerLeg * leg + 2] = pose[2];
  }
  keyframes_.push_back(frame);
  total_s_ += duration_s;
}

void SelfRighting::start(const RobotState&, BodyRest rest, BodyRest roll_to) {
  keyframes_.clear();
  total_s_ = 0.0;
  started_ = false;
  elapsed_s_ = 0.0;
  if (rest == BodyRest::Upright) return;
  // routines are written for the right side below; the left side mirrors them
  const bool mirror = rest == BodyRest::OnLeftSide || (rest == BodyRest::UpsideDown && roll_to == BodyRest::OnLeftSide);
  add(kFolded, kFolded, mirror, config_.fold_s);
  if (rest == BodyRest::UpsideDown) {
    // on the back: the left legs swing over the back into the ground and lever the robot onto its right side
    const std::array<double, 3> push_out{-kPushBehindBack[0], kPushBehindBack[1], kPushBehindBack[2]};
    const std::array<double, 3> lean_out{-0.68, 0.3, -0.6};
    add(kFolded, kOverTheBack, mirror, config_.reach_s);
    add(lean_out, push_out, mirror, config_.push_s);
    add(lean_out, push_out, mirror, config_.hold_s);
    return;
  }
  // on the right side: right legs over the back and into the ground, left legs out on the belly side
  add(kOverTheBack, kReachOut, mirror, config_.reach_s);
  add(kPushBehindBack, kReachOut, mirror, config_.push_s);
  add(kPushBehindBack, kReachOut, mirror, config_.hold_s);
}

double SelfRighting::progress() const { return total_s_ > 0.0 ? std::clamp(elapsed_s_ / total_s_, 0.0, 1.0) : 1.0; }

void SelfRighting::compute(const RobotState& state, JointCommand& command) {
  if (!started_) {
    started_ = true;
    start_time_s_ = state.time_s;
    start_q_ = state.q;
  }
  elapsed_s_ = state.time_s - start_time_s_;
  // find the keyframe being moved to; the first move starts from the joints as they were
  double t = elapsed_s_;
  const JointArray<double>* from = &start_q_;
  const JointKeyframe* to = keyframes_.empty() ? nullptr : &keyframes_.back();
  double fraction = 1.0;
  for (const JointKeyframe& frame : keyframes_) {
    if (t < frame.duration_s) {
      to = &frame;
      fraction = smooth_step(t / frame.duration_s);
      break;
    }
    t -= frame.duration_s;
    from = &frame.q;
  }
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    const double target = to == nullptr ? state.q[i] : (*from)[i] + (to->q[i] - (*from)[i]) * fraction;
    command.q_des[i] = target;
    command.qd_des[i] = 0.0;
    command.kp[i] = config_.kp;
    command.kd[i] = config_.kd;
    command.tau_ff[i] = 0.0;
  }
}

}  // namespace cerebellum
