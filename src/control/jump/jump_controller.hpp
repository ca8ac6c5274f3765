// A jump from a stand, as planned by plan_jump: crouch (the QP stand lowers the trunk), push
// (the trunk accelerates along the planned straight line: ground forces for m (a + g) and the
// turn, shared among the four feet by ForceDistribution, plus a soft joint PD along the same
// path), flight (the legs swing to the landing pose, feet below the hips, ahead by the planned
// offset), touchdown (foot force from the joint torques, or the planned time), landing (the QP
// stand anchored at the new feet absorbs the fall and brakes the trunk, then centres it) and the
// stand. A landing that goes wrong (trunk tilted or sunk past what a stand recovers) damps the
// joints and says so: the state machine's usual protection and recovery stand take over.
#pragma once

#include <array>

#include <Eigen/Core>

#include "core/robot_model.hpp"
#include "control/force_distribution.hpp"
#include "control/jump/jump_plan.hpp"
#include "control/qp_stand.hpp"
#include "control/stance_frame.hpp"
#include "core/robot_state.hpp"
#include "core/types.hpp"

namespace cerebellum {

struct JumpControllerConfig {
  JumpLimits limits;
  double crouch_duration_s = 0.4;
  double crouch_settle_s = 0.1;
  // push: trunk tracking on top of the planned acceleration (per m, per m/s as accelerations)
  Eigen::Vector3d push_kp{150.0, 150.0, 150.0};
  Eigen::Vector3d push_kd{20.0, 20.0, 20.0};
  Eigen::Vector3d push_orientation_kp{300.0, 300.0, 150.0};
  Eigen::Vector3d push_orientation_kd{25.0, 25.0, 20.0};
  ForceDistributionConfig push_distribution{0.75, 260.0, (Vector6d() << 1.0, 1.0, 1.0, 40.0, 40.0, 40.0).finished(),
                                            1e-4};
  // past its planned time the push goes on until the trunk is this fast (share of the planned
  // velocity), the legs this much further extended, or this share of the time has passed
  double takeoff_speed_fraction = 0.97;
  double push_extra_height_m = 0.02;
  double push_overrun_fraction = 1.4;
  double push_joint_kp = 20.0;
  double push_joint_kd = 0.5;
  // the push's progress up to this share of its planned time predicts the take-off velocity
  double push_measured_fraction = 0.75;
  // flight: the legs swing to the landing pose in this time
  double swing_duration_s = 0.12;
  // landing placement, from the take-off as it happened: the leading feet (along the jump) land
  // ahead of the mean offset by this share of it and the trailing feet behind it, those at most
  // this far ahead of their stand place (further, the trunk stopped by the leading legs sits down
  // behind them); a leg reaches at most this share of its full length (thigh + shank)
  double landing_spread_fraction = 0.5;
  double landing_trailing_offset_max_m = 0.1;
  double landing_leg_extension = 0.98;
  double flight_joint_kp = 50.0;
  double flight_joint_kd = 1.2;
  // touchdown: a foot carrying this much (from its joint torques) after this share of the flight
  double touchdown_force_n = 30.0;
  double touchdown_earliest_fraction = 0.5;
  double touchdown_latest_extra_s = 0.15;  // past the planned touchdown: landed whatever the feet say
  // landing: braking (no position hold) this long, then the trunk is centred over the feet
  double landing_brake_s = 0.4;
  double landing_centre_s = 0.6;
  QpStandConfig stand;
  // a landing past these has failed: damping
  double failed_tilt_rad = 0.8;
  double failed_height_m = 0.1;
  double damping_kd = robot::kDampingKd;
};

JumpControllerConfig default_jump_controller_config();

enum class JumpPhase { Idle, Crouch, Push, Flight, Landing, Standing, Failed };

const char* jump_phase_name(JumpPhase phase);

class JumpController {
 public:
  explicit JumpController(const JumpControllerConfig& config = default_jump_controller_config());

  // plan the jump and start crouching from the current stand
  void start(const RobotState& state, const JumpTarget& target);
  // start with a plan made elsewhere (the force jump plans from an acceleration)
  void start(const RobotState& state, const JumpPlan& plan);
  void compute(const RobotState& state, JointCommand& command);
  // no jump: stand where the robot is (finished)
  void hold(const RobotState& state);
  // a flight flown elsewhere (a played flip) has come down on its feet: land from here as a jump
  // lands (the stand anchored at the feet brakes, then centres the trunk; a failed landing damps)
  void land(const RobotState& state);

  JumpPhase phase() const { return phase_; }
  // 0..1 across crouch, push, flight and landing (1 once it stands, or failed)
  double progress() const;
  bool finished() const { return phase_ == JumpPhase::Standing || phase_ == JumpPhase::Failed; }
  bool failed() const { return phase_ == JumpPhase::Failed; }
  const JumpPlan& plan() const { return plan_; }
  const JumpControllerConfig& config() const { return config_; }

 private:
  void begin_push(const RobotState& state);
  void begin_flight(const RobotState& state);
  void begin_landing(const RobotState& state);
  // the take-off velocity the push is on course for (stance frame)
  void measure_push_progress(const RobotState& state);
  // where each foot lands relative to its stand place: what ends the stand at the plan's
  // displacement from the take-off the push really gave
  void place_landing();
  void push(const RobotState& state, JointCommand& command);
  void fly(const RobotState& state, JointCommand& command);
  bool push_done(const RobotState& state, double t) const;
  bool touched_down(const RobotState& state) const;
  bool landing_failed(const RobotState& state) const;

  JumpControllerConfig config_;
  JumpPlan plan_;
  QpStand stand_;
  StanceFrame frame_;
  ForceDistribution distribution_;
  JumpPhase phase_ = JumpPhase::Idle;
  double phase_start_s_ = 0.0;
  double start_s_ = 0.0;
  double last_time_s_ = 0.0;
  bool centred_ = false;
  Eigen::Vector3d start_position_ = Eigen::Vector3d::Zero();    // trunk when the jump began (stance frame)
  Eigen::Vector3d takeoff_velocity_ = Eigen::Vector3d::Zero();  // trunk, as the push's progress predicts it
  Eigen::Vector3d push_origin_ = Eigen::Vector3d::Zero();       // trunk at the push's start (stance frame)
  // each foot's landing place ahead of its stand place (take-off heading), set at take-off
  std::array<Eigen::Vector2d, kNumLegs> landing_offsets_{};
  JointArray<double> takeoff_q_{};
  std::array<Eigen::Vector3d, kNumLegs> stand_feet_{};  // before the jump, from the trunk (level axes)
  std::array<Eigen::Vector3d, kNumLegs> forces_{};
};

}  // namespace cerebellum
