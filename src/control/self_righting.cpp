#include "control/self_righting.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "control/stand_up_controller.hpp"
#include "core/robot_model.hpp"
#include "control/joint_ramp.hpp"

namespace cerebellum {
namespace {

using LegPose = std::array<double, 3>;  // abad, hip, knee (SDK convention)

// the roll over the right flank: poses of the right legs and the left legs
struct RollStep {
  LegPose right;
  LegPose left;
  double duration_s;
};

constexpr LegPose kFolded = robot::kLyingPose;
constexpr LegPose kLeverReady{-0.68, 2.75, -0.55};  // over the back, turned out
constexpr LegPose kLeverPush{0.68, 2.75, -0.55};    // swung in: the feet lever the flank up
constexpr LegPose kOverTheBack{-0.55, 2.75, -0.55};
constexpr LegPose kReachOut{0.0, 0.0, -0.55};
constexpr std::array<RollStep, 6> kRollOverRightFlank{{
    {kFolded, kFolded, 0.5},
    {{0.30, 1.01, -0.89}, kLeverReady, 0.6},
    {{-0.28, 1.33, -1.12}, kLeverPush, 0.15},
    {kOverTheBack, {-0.12, 1.18, -0.77}, 0.5},
    {kOverTheBack, kReachOut, 0.5},
    {kOverTheBack, kReachOut, 1.0},
}};

}  // namespace

BodyRest body_rest(const Eigen::Quaterniond& body_to_world) {
  const Eigen::Vector3d down = body_to_world.conjugate() * Eigen::Vector3d(0.0, 0.0, -1.0);
  // upright while tilted by less than 1 rad
  if (down.z() < -std::cos(1.0)) return BodyRest::Upright;
  if (std::abs(down.y()) > std::abs(down.z())) return down.y() < 0.0 ? BodyRest::OnRightSide : BodyRest::OnLeftSide;
  return down.z() > 0.0 ? BodyRest::UpsideDown : BodyRest::Upright;
}

SelfRighting::SelfRighting(const SelfRightingConfig& config) : config_(config) {
  keyframes_.reserve(kRollOverRightFlank.size());
}

void SelfRighting::start(BodyRest roll_over) {
  keyframes_.clear();
  total_s_ = 0.0;
  elapsed_s_ = 0.0;
  started_ = false;
  // over the left flank: the mirror image (legs swap sides, abad angles change sign)
  const bool mirror = roll_over == BodyRest::OnLeftSide;
  for (const RollStep& step : kRollOverRightFlank) {
    JointKeyframe frame;
    frame.duration_s = step.duration_s;
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      const bool right = leg_side_sign(leg) < 0.0;
      const LegPose& pose = (right != mirror) ? step.right : step.left;
      frame.q[kJointsPerLeg * leg] = mirror ? -pose[0] : pose[0];
      frame.q[kJointsPerLeg * leg + 1] = pose[1];
      frame.q[kJointsPerLeg * leg + 2] = pose[2];
    }
    keyframes_.push_back(frame);
    total_s_ += step.duration_s;
  }
}

double SelfRighting::progress() const { return total_s_ > 0.0 ? std::clamp(elapsed_s_ / total_s_, 0.0, 1.0) : 1.0; }

void SelfRighting::compute(const RobotState& state, JointCommand& command) {
  if (!started_) {
    started_ = true;
    start_time_s_ = state.time_s;
    start_q_ = state.q;
  }
  elapsed_s_ = state.time_s - start_time_s_;
  // the keyframe being moved to; the first move starts from the joints as they were
  double t = elapsed_s_;
  const JointArray<double>* from = &start_q_;
  const JointArray<double>* to = keyframes_.empty() ? &start_q_ : &keyframes_.back().q;
  double fraction = 1.0;
  for (const JointKeyframe& frame : keyframes_) {
    if (t < frame.duration_s) {
      to = &frame.q;
      fraction = smooth_step(t / frame.duration_s);
      break;
    }
    t -= frame.duration_s;
    from = &frame.q;
  }
  ramp_joints(*from, *to, fraction, config_.kp, config_.kd, command);
}

}  // namespace cerebellum
