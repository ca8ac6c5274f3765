// Mode 11's walking controller: gait schedule, convex MPC for the stance forces (in its own
// thread), Bezier swing trajectories to Raibert footholds, and the joint commands of both.
// Footholds, height and attitude references stand on the estimator's ground plane (state.ground).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>

#include "control/leg_gravity.hpp"
#include "control/locomotion/convex_mpc.hpp"
#include "control/locomotion/foothold.hpp"
#include "control/locomotion/gait.hpp"
#include "control/locomotion/swing_trajectory.hpp"
#include "control/locomotion/mpc_worker.hpp"
#include "control/locomotion/slip_watch.hpp"
#include "core/contact_plan.hpp"
#include "core/robot_model.hpp"
#include "core/robot_state.hpp"
#include "core/types.hpp"

namespace cerebellum {

struct LocomotionConfig {
  double tick_s = 0.002;
  int ticks_per_segment = 15;  // kGaitSegmentS at 500 Hz (the MC sets it from its loop period)
  ConvexMpcConfig mpc;
  FootholdConfig foothold;
  double default_height_m = robot::kWalkHeightM;
  double hop_step_height_fraction = 0.3;  // pronk: share of the step height the feet are lifted
  double swing_kp = 40.0;                 // joint gains tracking the swing trajectory (motor PD at 1 kHz)
  double swing_kd = 1.0;
  // joint damping toward a foot at rest on the ground; its forces are outside the MPC's friction
  // cone, and at 0.8 they made loaded feet slip in turns; at 0.2 a 15 N s push fell
  double stance_kd = 0.25;
  // ... and, with slip_response on, on a ground the feet slide on (slip_watch): there the damping
  // is what holds a sliding foot back, and the MPC keeps its forces in the diamond pyramid
  // (FrictionPyramid::Diamond, within the friction coefficient in every direction). On a floor of
  // friction 0.43 either alone left about half the falls, both always on none, but on the model's
  // floor both always on fell more than today's tuning; switched by the watch, 11 falls where
  // there were 58 on 0.43, 2 where there were 0 on the model's floor (tuning seeds,
  // docs/benchmarks/locomotion-log.md, 2026-12-02). Off: the product's tuning
  bool slip_response = false;
  double slippery_stance_kd = 0.8;
  // ... and there the commanded velocity changes slower and turns at speed are wider: the ramps
  // (max_accel_m_s2, max_yaw_accel_rad_s2) times this share, and |v| |yaw rate| clamped at
  // slippery_centripetal_accel_m_s2 instead of max_centripetal_accel_m_s2
  double slippery_ramp_share = 0.5;
  double slippery_centripetal_accel_m_s2 = 0.8;
  SlipWatchConfig slip_watch;
  // slow integral on the height error: joint friction otherwise leaves a steady offset
  double height_integral_gain = 2.0;  // 1/s
  double height_integral_limit_m = 0.03;
  // ramp of the commanded velocity; at 2.0 m/s^2 and 6 rad/s^2 changes of command (a turn
  // reversed at speed) fell in the soak twice as often
  double max_accel_m_s2 = 1.2;
  double max_yaw_accel_rad_s2 = 3.0;
  // time constant of the ramped command low-passed (s): the command a push is judged against
  // besides the current one (raibert_foothold)
  double push_reference_time_constant_s = 1.0;
  // the position reference runs at most this far from the trunk (m)
  double max_position_lag_m = 0.1;
  // integral action on the walking velocity error (1/s; 0: off, the product's tuning): the
  // estimated trunk velocity falling short of the ramped command adds to the MPC's reference
  // velocity, at most velocity_trim_max_fraction of the command on each axis (none trotting in
  // place) and only while the error is under velocity_trim_error_window_m_s (a push is no drag to
  // integrate). config/extended.yaml turns it on: the flying trot at 2.5 m/s fell 5 % short of its
  // own estimate without it (docs/benchmarks/locomotion-log.md, 2026-12-01)
  double velocity_trim_gain_per_s = 0.0;
  double velocity_trim_max_fraction = 0.25;
  double velocity_trim_error_window_m_s = 0.5;
  // a swing foot that meets the ground before its planned touchdown (the top of a step or a stair,
  // where the blind MC plans flat ground) is held where it met it, instead of being driven on down
  // to the planned height: the ground's upward force on it (from its joint torques) above this in
  // the swing's second half (N). 0: off, the product's tuning; config/extended-terrain.yaml turns it
  // on (it costs falls on flat ground: docs/terrain.md)
  double early_touchdown_force_n = 0.0;
  // ... from this share of the swing on: before it the swing's turn at its apex reads as up to
  // 240 N on a foot in the air (a 12 cm swing of the slow trot on flat ground), after 0.6 under 20 N
  double early_touchdown_from_phase = 0.6;
  // ... while the foot stands this far above its planned path (m): in the air it trails the path
  // by 0 to 3 cm below and is never more than 3 mm above it (flat ground, the same swing) ...
  double early_touchdown_above_path_m = 0.01;
  // ... for this many ticks in a row: a swing target that jumps (the ground plane turning as
  // another foot lands) reads as +-300 N for two or three ticks
  int early_touchdown_ticks = 5;
  // a foot whose stance is due while nothing holds it up yet (the ground lower than planned: off a
  // step) reaches on down at this speed, out of the MPC's stance feet, until the ground pushes
  // back (early_touchdown_force_n, late_touchdown_ticks in a row) or it is this far below where its
  // stance was due (m). 0: off, the product's tuning (the stance's forces drive it down instead)
  double late_touchdown_reach_m = 0.0;
  double late_touchdown_reach_speed_m_s = 1.0;
  int late_touchdown_ticks = 2;
  // ... only in stances at least this long (s): a foot that reaches is out of the MPC's plan for a
  // whole 30 ms segment, which the slow trot's 0.36 s stance spares and the flying trot's 0.12 s
  // does not (with reaching on, it made 0.74 m/s of a commanded 2.5)
  double late_touchdown_min_stance_s = 0.3;
  // a swing aims at the ground its foot lifted from, tilted by the ground plane between there and
  // the foothold, instead of at the plane itself: the plane through four feet of which one or two
  // stand on a step lies between the step and the floor, and a rear foot aiming at it stopped in
  // the air above the floor
  bool foothold_on_own_ground = false;
  // a new gait starts once the ramped velocity is this close to its limits (m/s, rad/s)
  double gait_switch_velocity_margin = 0.05;
  // ... and once the body's measured velocity is this close to them (m/s)
  double gait_switch_body_margin_m_s = 0.15;
  // between two stepping gaits all feet stand this many segments (0: none): the old gait's last
  // stance leaves the body pitching or rolling (a bound up to 4 rad/s), and the new gait's first
  // swing pair would otherwise lift the legs that have to stop it; longer bridges fell more, the
  // feet stand while the body moves on
  int gait_bridge_segments = 1;
  // ... and this many after a gait that stands on lone pairs (the bound): its cycle ends with the
  // rear pair landing while the trunk pitches at 3-5 rad/s, and the trot after one segment's bridge
  // could not stop the swing (in the soak, 3 of 5 falls, 50 of 68 near falls outside the bound).
  // The bound moves at 0.3 m/s at most, so its feet fall little behind while they stand; the
  // trunk is left up to 0.2 rad nose-up, which the slow trot does not always carry (benchmarks.md)
  int lone_pair_exit_bridge_segments = 3;
  // a trot that leaves a stand (not the bridge) while the body moves sideways faster than this
  // (m/s) begins with the diagonal that catches it (sideways_entry_segment). After a bridge it
  // does not: choosing there by sideways speed fell more often in the soak (out of the bound the
  // diagonal nearer the centre of mass stands first, diagonal_entry_segment)
  double sideways_entry_speed_m_s = 0.1;
  // |v| |yaw rate| above this (m/s^2) is clamped by lowering the yaw rate: friction 0.4 allows at
  // most 3.9 m/s^2 with no margin for the gait's own forces. At 2.0 a fast turning trot slid
  // sideways 0.3 m/s off its command and the soak's falls came mostly from such turns; at 1.5
  // about 0.22 m/s, and half the soak's near falls outside the bound (2.5 fell more still)
  double max_centripetal_accel_m_s2 = 1.5;
  double vertical_leg_half_width_m = robot::kHipY + robot::kAbadLength;  // value bit1 = 1: feet under the hips
  double pigeon_toe_half_width_m = 0.11;  // value bit1 = 0: energy-saving narrower stance
  // the point the MPC takes its lever arms from (body frame): a tuned point, NOT the centre of
  // mass. The centre of mass has one home, stand_com_in_body() (leg_gravity: 0.0064 m ahead of the
  // trunk origin), which the stands and the footholds use; with it as the MPC's origin a user
  // gait's end stood pitched 0.053 rad and gait 1's sideways catch was lost before the stands held
  // position. The walking gaits and the soak were tuned with 0.013 m (a change needs a new soak)
  Eigen::Vector3d mpc_lever_arm_origin_body{0.013, 0.0, 0.0};
  int failed_solves_to_give_up = 3;
  // swing feet are kept this far inside the interface's foot workspace (safety/body_watch)
  double workspace_margin_m = 0.02;
};

// what a step of a user gait adds to the target (the gait's schedule comes from play())
struct UserStepTargets {
  // where each swing foot lands: from the ground under its hip at touchdown, body x, y (m)
  std::array<Eigen::Vector2d, kNumLegs> landing_offset_m{};
  std::array<double, kNumLegs> step_height_m{};  // each leg's swing height
  double landing_gain = 1.0;                     // scales the velocity feedback on the landing points
  double roll_rad = 0.0;
  double yaw_offset_rad = 0.0;  // from the yaw the commanded yaw rate integrates to
  double friction = 0.0;        // the MPC's friction coefficient; 0: the configured one
  // the step moves the body by position (body_pos_des), not velocity: while every foot stands
  // through the MPC's horizon the position weighs like a holding stand's. At the walking weight
  // the trunk leaned 2.8 of 5 cm forward in the step's 1.2 s; with it, 4.6
  bool leans_to_position = false;
};

struct LocomotionTarget {
  GaitPattern gait;
  Eigen::Vector3d velocity{0, 0, 0};  // vx, vy (body frame, m/s), yaw rate (rad/s); clamped to the gait
  double height_m = robot::kWalkHeightM;
  double pitch_rad = 0.0;
  double step_height_front_m = kDefaultStepHeightM;
  double step_height_rear_m = kDefaultStepHeightM;
  bool vertical_legs = false;
  // a stand of the gait table (11/1, 11/31): while every foot is down through the MPC's horizon
  // the trunk is held over the middle of the feet (ConvexMpcConfig::stand_position_weight); the
  // passive trot's and a user gait's stands stay soft
  bool stand_holds_position = false;
  // the trot is gait 1's catch of a push on the spot (FootholdConfig::catch_lateral_velocity_gain)
  bool catching_push = false;
  std::optional<UserStepTargets> user_step;  // a user gait's step; none for the table's gaits
};

struct LocomotionTelemetry {
  std::uint64_t mpc_solves = 0;
  std::uint64_t mpc_failures = 0;
  int last_variables = 0;
  qp::QpStatus last_status = qp::QpStatus::Solved;
};

class LocomotionController {
 public:
  LocomotionController(const LocomotionConfig& config, std::unique_ptr<qp::QpSolver> solver);

  // start walking from the current state: every foot in stance where it stands
  void reset(const RobotState& state);
  // false (and nothing changes) when a number in the command is not finite; velocities are
  // clamped to the gait's limits
  bool set_command(const LocomotionTarget& command);
  void compute(const RobotState& state, JointCommand& command);
  // play a contact sequence once (a user gait) from the current state; the pattern of the
  // target waits until it ends; set_command() steers the body and the swing legs meanwhile
  void play(std::shared_ptr<const ContactSequence> sequence, const RobotState& state);
  // the position reference jumps to the trunk: the controller keeps tracking velocity but no
  // longer pulls the trunk back to where the commands alone would have taken it (a gait that lets
  // outside forces move the robot)
  void anchor_position_at_trunk(const RobotState& state) { position_des_ = state.position_world.head<2>(); }

  // false after several failed MPC solves in a row: the caller must switch to a safe behaviour
  bool healthy() const { return consecutive_failures_ < config_.failed_solves_to_give_up; }
  const LocomotionTelemetry& telemetry() const { return telemetry_; }
  const GaitScheduler& scheduler() const { return scheduler_; }
  // what the feet have told of the ground; kept across reset(): the ground stays what it was
  const SlipWatch& slip_watch() const { return slip_watch_; }
  // the stance legs and the MPC act for a slippery ground now (LocomotionConfig::slip_response)
  bool responding_to_slip() const { return config_.slip_response && slip_watch_.slippery(); }
  const Eigen::Vector3d& ramped_velocity() const { return velocity_; }
  // each leg's place in the schedule; after compute(), the contacts planned for the next tick
  ContactSchedule contact_schedule() const;
  // a stand gait runs (every foot down, not the bridge between two stepping gaits): its schedule
  // says nothing a shove could not undo. A push tips the trunk off its far feet while the stand
  // still has them down; trusted, they moved with the trunk, read it at rest, and the velocity
  // estimate said 0.05 m/s for a true 0.7
  bool standing() const { return !steps(scheduler_.pattern()) && !scheduler_.playing() && !bridging_; }

 private:
  void ramp_velocity();
  // the integral action on the velocity error (velocity_trim_gain_per_s)
  void update_velocity_trim(const RobotState& state);
  void change_pattern_if_due(const RobotState& state);
  // one tick of a leg for the slip watch: a planted foot's horizontal speed over the ground
  void observe_slip(std::size_t leg, const LegPhase& phase, const RobotState& state, const Eigen::Matrix3d& body_to_world);
  void post_mpc(const RobotState& state);
  void collect_mpc();
  // where a swinging foot (its centre) will land
  Eigen::Vector3d foothold_world(std::size_t leg, const LegPhase& phase, const RobotState& state) const;
  void command_swing_leg(std::size_t leg, const LegPhase& phase, const RobotState& state, JointCommand& command);
  // the leg's joints track a foot point (world) with the swing gains
  void track_foot_point(std::size_t leg, const SwingPoint& point, const RobotState& state, JointCommand& command) const;
  // a foot reaching down for ground that lies lower than planned (late_touchdown_reach_m)
  void command_reaching_leg(std::size_t leg, const RobotState& state, JointCommand& command);
  // the ground's upward force on the foot is above early_touchdown_force_n
  bool ground_pushes_back(std::size_t leg, const RobotState& state) const;
  void command_stance_leg(std::size_t leg, const RobotState& state, JointCommand& command);
  Eigen::Vector3d hip_on_ground_world(std::size_t leg, const RobotState& state, double ahead_s,
                                      double yaw_ahead_s) const;

  LocomotionConfig config_;
  // the robot's own centre of mass in the stand, where a holding stand puts it over the feet
  Eigen::Vector3d stand_com_body_ = stand_com_in_body();
  ConvexMpc mpc_;
  MpcWorker worker_;
  GaitScheduler scheduler_;
  SlipWatch slip_watch_;
  LocomotionTarget target_;
  GaitPattern pending_gait_;
  bool gait_change_pending_ = false;
  bool bridging_ = false;  // the scheduler runs the stand bridge between two gaits
  GaitPattern gait_before_bridge_;
  Eigen::Vector3d velocity_{0, 0, 0};         // ramped command
  Eigen::Vector3d velocity_before_{0, 0, 0};  // the ramped command low-passed
  double yaw_des_ = 0.0;
  Eigen::Vector2d position_des_{0, 0};  // world x, y
  Eigen::Vector2d velocity_trim_{0, 0};  // body x, y (m/s), added to the MPC reference velocity
  double height_correction_m_ = 0.0;
  int tick_in_segment_ = 0;
  std::array<bool, kNumLegs> was_stance_{};
  std::array<Eigen::Vector3d, kNumLegs> swing_start_{};
  // per leg: its swing met the ground early (early_touchdown_force_n), and where (world)
  std::array<bool, kNumLegs> touched_early_{};
  std::array<int, kNumLegs> touching_ticks_{};  // ticks in a row that looked like a touchdown
  // per leg: its stance is due but it still reaches down for the ground (late_touchdown_reach_m)
  std::array<bool, kNumLegs> reaching_{};
  std::array<double, kNumLegs> reach_elapsed_s_{};
  std::array<Eigen::Vector3d, kNumLegs> reach_from_world_{};
  std::array<Eigen::Vector3d, kNumLegs> early_touchdown_world_{};
  // body to world rotation the swing legs use: the measured one, frozen while all feet are in the air
  Eigen::Matrix3d swing_frame_ = Eigen::Matrix3d::Identity();
  bool in_flight_ = false;
  std::array<Eigen::Vector3d, kNumLegs> forces_{};
  MpcInput mpc_input_;
  MpcOutput mpc_output_;
  int consecutive_failures_ = 0;
  LocomotionTelemetry telemetry_;
};

}  // namespace cerebellum
