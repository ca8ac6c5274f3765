// Mode 21: position-based pose control. The feet stay on their footholds (stance frame anchored
// on entry); the body pose is reached by inverse kinematics, the joints by PD with a gravity
// feedforward shared among the loaded feet.
//   gait 0: rpy_des and pos_des are a pose about the stand pose (ctrl_point: rotation centre);
//   gait 5: pos_des[2] is the absolute height (duration > 0), which becomes the stand height;
//   gait 2: swing one leg (contact bits) to its foot_pose offset after shifting the weight;
//   gait 3: hold the pose reached so far.
// Contact bits and foot_pose apply in gaits 0, 2 and 5.
#pragma once

#include "control/leg_gravity.hpp"
#include "control/force_distribution.hpp"
#include "control/orientation_trim.hpp"
#include "control/pose_ramp.hpp"
#include "control/support_sequence.hpp"
#include "core/robot_model.hpp"
#include "modes/command_ranges.hpp"
#include "modes/mode.hpp"

namespace cerebellum {

// mode 21's gaits that other code asks for: hold the pose reached so far; the absolute height
inline constexpr int kPoseHoldGait = 3;
inline constexpr int kPoseAbsoluteHeightGait = 5;

struct PoseControlConfig {
  PoseControlRanges ranges;
  FootOffsetRanges foot_offset;
  PoseSpeed speed{0.8, 0.12, 0.3};
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

 private:
  // body pose (stance frame) a gait 0 / 5 command asks for
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
  double base_height_m_ = 0.0;
  double last_time_s_ = 0.0;
  bool started_ = false;
  int gait_ = 0;
  bool timed_ = false;
};

}  // namespace cerebellum
