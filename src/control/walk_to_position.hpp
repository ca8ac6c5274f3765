// Walking to a target position and heading (the AlienGo interface's mode 3): the body-frame
// velocity and yaw rate that take the trunk there and stop it there. The robot walks sideways and
// backwards as needed instead of turning first, so it arrives instead of orbiting the target.
#pragma once

#include <Eigen/Core>

namespace cerebellum {

struct WalkToPositionConfig {
  double position_gain_per_s = 1.2;  // velocity per metre of error, before the speed limit
  double yaw_gain_per_s = 1.5;       // yaw rate per radian of heading error
  double max_yaw_rate_rad_s = 0.8;
  double max_lateral_share = 0.5;   // lateral speed limit as a share of the speed limit
  double arrive_position_m = 0.03;  // within this and arrive_yaw_rad: arrived, stand
  double arrive_yaw_rad = 0.05;
  double leave_position_m = 0.08;  // once arrived, walk again only beyond these
  double leave_yaw_rad = 0.15;
};

struct Pose2d {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // world x, y (m)
  double yaw_rad = 0.0;
};

struct WalkToPositionOutput {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // vx, vy (body frame, m/s), yaw rate (rad/s)
  bool arrived = false;
};

class WalkToPosition {
 public:
  explicit WalkToPosition(const WalkToPositionConfig& config = {}) : config_(config) {}

  // a new target: walking starts again unless already there
  void reset() { arrived_ = false; }
  // the command for this moment; max_speed_m_s: the speed level's limit
  WalkToPositionOutput update(const Pose2d& trunk, const Pose2d& target, double max_speed_m_s);

 private:
  WalkToPositionConfig config_;
  bool arrived_ = false;
};

}  // namespace cerebellum
