// Force-based stand (the QP stand): a PID on the body pose (position, velocity and a small
// integral on height and orientation) gives the wrench the ground must apply, ForceDistribution
// shares it among the loaded feet, and the legs make those forces with tau = G(q) - J' R' f
// (G: the leg's own weight). Loaded legs also get a soft joint PD to the pose the target asks for
// (the joints' dry friction would otherwise hold the body off target); legs in the air follow a
// foot target with a stiffer joint PD. The pose is estimated from the stance feet's kinematics.
#pragma once

#include <array>

#include <Eigen/Core>

#include "control/leg_gravity.hpp"
#include "control/force_distribution.hpp"
#include "control/orientation_trim.hpp"
#include "control/stance_frame.hpp"
#include "core/robot_model.hpp"
#include "core/robot_state.hpp"
#include "core/types.hpp"

namespace cerebellum {

struct BalanceConfig {
  double mass_kg = robot::kTotalMassKg;
  Eigen::Vector3d inertia_diag{robot::kMpcInertiaDiag[0], robot::kMpcInertiaDiag[1], robot::kMpcInertiaDiag[2]};
  // centre of mass of the whole robot in the body frame (trunk COM weighted with the legs)
  Eigen::Vector3d com_in_body = stand_com_in_body();
  // PD gains as accelerations: per m (1/s^2) and per m/s (1/s), per rad and per rad/s
  Eigen::Vector3d kp_position{60.0, 60.0, 200.0};
  Eigen::Vector3d kd_position{12.0, 12.0, 20.0};
  Eigen::Vector3d kp_orientation{200.0, 200.0, 150.0};
  Eigen::Vector3d kd_orientation{16.0, 16.0, 14.0};
  // integral action on height and orientation: removes the sag from leg weight and joint friction
  double ki_height = 100.0;                             // 1/s^3
  Eigen::Vector3d ki_orientation{100.0, 100.0, 100.0};  // 1/s^3
  double max_integral_height_acceleration = 3.0;        // m/s^2
  double max_integral_angular_acceleration = 10.0;      // rad/s^2
  double integrate_below_height_error_m = 0.03;         // larger errors (a big move under way) are not integrated
  double integrate_below_angle_error_rad = 0.1;
  double max_tilt_acceleration = 30.0;     // rad/s^2 cap on the orientation PD
  double max_position_acceleration = 6.0;  // m/s^2 cap on the horizontal PD
  ForceDistributionConfig distribution;
  // loaded legs also get a joint PD to the pose the target asks for: the joints' dry friction
  // (0.1-0.25 N m) would otherwise hold the body up to ~0.1 rad away from it
  double stance_kp = 25.0;
  double stance_kd = 0.6;
  double swing_kp = 40.0;
  double swing_kd = 1.5;
  OrientationTrimConfig trim;  // on the orientation the stance joints' PD is set for
};

// where the body should be and what each leg does (stance frame)
struct BalanceTarget {
  BodyPose pose;
  BodyPose rate;  // d/dt of pose: rpy rates and linear velocity (feedforward of a moving target)
  // false: horizontal velocity is damped but the position is not pulled back
  bool hold_position_xy = true;
  // per leg: the largest normal force it may carry; 0 with in_air set: foot follows swing_foot
  std::array<double, kNumLegs> force_z_max_n{150.0, 150.0, 150.0, 150.0};
  LegMask in_air{false, false, false, false};
  std::array<Eigen::Vector3d, kNumLegs> swing_foot{};
};

class BalanceController {
 public:
  explicit BalanceController(const BalanceConfig& config = {});

  // anchor the stance frame at the current feet, forget the integrators
  void start(const RobotState& state);
  // dt_s: time since the last compute (integrators)
  void compute(const RobotState& state, const BalanceTarget& target, double dt_s, JointCommand& command);

  const StanceFrame& frame() const { return frame_; }
  // the body pose estimated at the last compute (stance frame)
  const BodyPose& estimated_pose() const { return estimated_pose_; }
  // body origin that puts the centre of mass at com_xy with the given orientation (stance frame)
  Eigen::Vector2d body_xy_for_com(const Eigen::Vector2d& com_xy, const Eigen::Vector3d& rpy) const;

 private:
  BalanceConfig config_;
  StanceFrame frame_;
  ForceDistribution distribution_;
  OrientationTrim trim_;
  LegMask was_in_air_{};
  BodyPose estimated_pose_;
  Eigen::Vector3d estimated_velocity_ = Eigen::Vector3d::Zero();
  Vector6d wrench_ = Vector6d::Zero();
  double height_integral_ = 0.0;                              // m/s^2
  Eigen::Vector3d angle_integral_ = Eigen::Vector3d::Zero();  // rad/s^2
  // forces of the last successful solve: kept when a solve fails
  std::array<Eigen::Vector3d, kNumLegs> forces_{};
  std::array<Eigen::Vector3d, kNumLegs> solved_forces_{};
};

// wrench that keeps a body of this mass at rest against gravity with no torque
Vector6d gravity_wrench(double mass_kg);

}  // namespace cerebellum
