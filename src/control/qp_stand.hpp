// The QP stand as a behaviour: BalanceController driven towards a goal pose along a smooth
// ramp, with one leg taken off the ground (and put back) by a SupportSequence. Used by the
// force-based pose mode (3) and by locomotion's stand gaits (11 / 1, 31).
#pragma once

#include "control/balance_controller.hpp"
#include "control/pose_ramp.hpp"
#include "control/support_sequence.hpp"

namespace cerebellum {

struct QpStandGoal {
  // rpy: roll, pitch, yaw (yaw relative to the stance frame); position: x, y offset from the
  // centred stand (centre of mass over the footholds' centroid), z height above the ground
  BodyPose pose;
  int lifted_leg = SupportSequence::kNoLeg;
  Eigen::Vector3d lifted_foot_offset = Eigen::Vector3d::Zero();  // from its foothold
  bool hold_position_xy = true;
};

struct QpStandConfig {
  BalanceConfig balance;
  SupportSequenceConfig support;
  double max_height_m = 0.29;  // legs near full stretch (knee limit) cannot balance above this
};

class QpStand {
 public:
  explicit QpStand(const QpStandConfig& config = {});

  // take over at the current pose
  void start(const RobotState& state);
  // move to a goal from the current pose, no faster than speed and taking at least min_duration_s
  void set_goal(const QpStandGoal& goal, const PoseSpeed& speed, double min_duration_s = 0.0);
  void compute(const RobotState& state, JointCommand& command);

  // 0..1: the pose move and the leg change done
  double progress() const;
  bool settled() const { return ramp_.arrived() && support_.settled(); }
  const BalanceController& controller() const { return controller_; }

 private:
  QpStandConfig config_;
  BalanceController controller_;
  PoseRamp ramp_;
  SupportSequence support_;
  QpStandGoal goal_;
  // per leg: the offset it was last asked to lift to (kept while it is put down again)
  std::array<Eigen::Vector3d, kNumLegs> foot_offsets_{};
  double last_time_s_ = 0.0;
  bool started_ = false;
};

}  // namespace cerebellum
