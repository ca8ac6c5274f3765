// Mode 21: position-based pose control. The feet stay on their footholds (stance frame anchored
// on entry); the body pose is reached by inverse kinematics, the joints by PD with a gravity
// feedforward shared among the loaded feet. The pose starts as the level stand on entry.
//   gait 0: incremental (the seed's "incremental position control"): rpy_des and pos_des move the
//           body from where the previous command left it, over the duration (ctrl_point: the
//           rotation centre); the sum is held inside the ranges, and a clamp is reported;
//   gait 5: absolute: pos_des[2] the height (duration > 0), rpy_des the attitude, x, y centred;
//   gait 2: as gait 0, and swing one leg (contact bits) to its foot_pose offset after shifting
//           the weight;
//   gait 3: hold the pose reached so far.
// Contact bits and foot_pose apply in gaits 0, 2 and 5. +pitch raises the head (commanded_pose).
#pragma once

#include "control/leg_gravity.hpp"
#include "control/force_distribution.hpp"
#include "control/orientation_trim.hpp"
#include "control/pose_ramp.hpp"
#include "control/support_sequence.hpp"
#include "core/robot_model.hpp"
#include "modes/command_ranges.hpp"
#include "modes/commanded_pose.hpp"
#include "modes/mode.hpp"

namespace cerebellum {

// mode 21's gaits that other code asks for: hold the pose reached so far; the absolute height
inline constexpr int kPoseHoldGait = 3;
inline constexpr int kPoseAbsoluteHeightGait = 5;

struct PoseControlConfig {
  PoseControlRanges ranges;
  FootOffsetRanges foot_offset;
  // an untimed command moves at most this fast; a timed one takes its duration (the seed: "how
  // long the body takes to move towards the target posture"), never faster than timed_speed
  PoseSpeed speed{0.8, 0.12, 0.3};
  PoseSpeed timed_speed{1.6, 0.12, 0.3};
  // a lifted foot moves to a new offset at most this fast (a hand shake's up and down): a jump
  // of the target swings the leg at the joints' torque limit
  double lifted_foot_speed_m_s = 0.4;
  SupportSequenceConfig support;
  double kp = 80.0;
  double kd = 2.0;
  double mass_kg = robot::kTotalMassKg;
  Eigen::Vector3d com_in_body = stand_com_in_body();
  ForceDistributionConfig distribution;
  OrientationTrimConfig trim;
};

class PoseControlMode final : public Mode {
 public:
  explicit PoseControlMode(const PoseControlConfig& config = {});
  ModeId id() const override { return ModeId::PoseControl; }
  const char* check(const HighLevelCommand& command) const override;
  void enter(const RobotState& state, const HighLevelCommand& command) override;
  void update(const RobotState& state, const HighLevelCommand& command) override;
  void run(const RobotState& state, JointCommand& command) override;
  int gait_id() const override { return gait_; }
  int progress_percent() const override;
  const char* clamp_note() const override { return clamp_note_; }

 private:
  // body pose (stance frame) of the commanded pose, about the command's control point
  BodyPose goal_pose(const HighLevelCommand& command);

  PoseControlConfig config_;
  StanceFrame frame_;
  PoseRamp ramp_;
  SupportSequence support_;
  ForceDistribution distribution_;
  OrientationTrim trim_;
  // per leg: the offset it was last asked to lift to (kept while it is put down again)
  std::array<Eigen::Vector3d, kNumLegs> foot_offsets_{};
  // per leg: where its offset is on the way to foot_offsets_ (rate-limited)
  std::array<Eigen::Vector3d, kNumLegs> offsets_now_{};
  CommandedPose pose_;                // what the commands asked for so far
  const char* clamp_note_ = nullptr;  // the last command's clamp, if any
  double last_time_s_ = 0.0;
  bool started_ = false;
  int gait_ = 0;
  bool timed_ = false;
};

}  // namespace cerebellum
