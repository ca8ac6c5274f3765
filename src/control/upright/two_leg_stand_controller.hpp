// Mode 64, the two-leg stand ("greeting"): from a stand the robot crouches with its weight over
// the hind feet (joint PD), rises onto them along the designed family of upright equilibria with
// the front legs folding (the LQR of upright_balance_design, scheduled on the rise's progress),
// holds the upright pose balanced, comes down the same way, puts the front feet down, returns to
// the joints it stood on and stands (QP stand). A balance lost past what the gain can catch
// (safety/upright_watch) damps the joints: the state machine's usual protection and recovery stand
// take over.
//
// The balance design runs once, on a worker thread started by the first command (~0.1 s); the
// robot holds its stand until it is ready.
#pragma once

#include <future>
#include <string>
#include <vector>

#include "core/robot_model.hpp"
#include "control/qp_stand.hpp"
#include "control/upright/upright_balance_design.hpp"
#include "control/upright/upright_state.hpp"
#include "core/robot_state.hpp"
#include "core/types.hpp"

namespace cerebellum {

struct TwoLegStandConfig {
  std::string model_path;  // the robot's MuJoCo model the balance is designed on
  double control_period_s = 0.002;
  UprightDesignConfig design;
  // the first command's design runs while the robot holds its stand this long; a design not
  // ready by then is waited for (in lockstep, where robot time runs faster than the design): the
  // motion's timing is the same whatever the computer's speed
  double design_wait_s = 0.3;
  // phases (s); the hold lasts the rest of the command's duration, at least min_hold_s
  double crouch_s = 1.2;
  double crouch_settle_s = 0.2;
  double rise_s = 3.0;
  double min_hold_s = 0.5;
  double lower_s = 2.5;
  double front_down_s = 0.5;
  double restand_s = 1.2;
  double stand_s = 0.3;
  // the reference's duration for mode 64 (cyberdog2-highlevel.md: > 8700 ms): the whole motion
  // lasts this long when the command gives no longer duration
  double reference_duration_s = 8.7;
  // joint PD of the crouch, of putting the front feet down and of the return to the stand
  double joint_kp = 80.0;
  double joint_kd = 2.0;
  double front_press_m = 0.005;  // the crouch's front feet this far into the ground: they bear on it
  // The balance's feedback is low-passed here (Hz), and the motor drivers damp each joint about
  // the reference's rate on their own fresh encoders. Through a link a tick or more slow each way
  // (the stacked pair, a real robot) the feedback alone set the stance legs oscillating (about
  // 125 Hz) until the robot fell; unfiltered, sensor noise made it chatter. Chosen on the
  // noiseless seed-0 stand with 0-6 ticks of latency each way (docs/benchmarks/
  // two-leg-stand-latency-log.md): 10 Hz and 4 Nm s/rad hold 12 s upright at every latency there;
  // 15 Hz failed from 3-4 ticks, 6-8 Nm s/rad made the long hold drift over.
  double feedback_cutoff_hz = 10.0;
  double balance_joint_kd = 4.0;
  double damping_kd = robot::kDampingKd;
  QpStandConfig stand;
};

enum class TwoLegPhase { Idle, Preparing, Crouch, Rise, Hold, Lower, FrontDown, Restand, Standing, Failed };

class TwoLegStandController {
 public:
  explicit TwoLegStandController(const TwoLegStandConfig& config);
  ~TwoLegStandController();
  TwoLegStandController(const TwoLegStandController&) = delete;
  TwoLegStandController& operator=(const TwoLegStandController&) = delete;

  // from a stand; duration_s: the command's (0: the reference's)
  void start(const RobotState& state, double duration_s);
  void compute(const RobotState& state, JointCommand& command);

  TwoLegPhase phase() const { return phase_; }
  // 0..1 of the whole motion's time; 1 once it stands again (or failed)
  double progress() const;
  bool finished() const {
    return phase_ == TwoLegPhase::Standing || phase_ == TwoLegPhase::Failed || phase_ == TwoLegPhase::Idle;
  }
  bool failed() const { return phase_ == TwoLegPhase::Failed; }
  // why the design could not be made (the robot model), empty while none failed
  const std::string& design_error() const { return design_error_; }
  // the designed family, empty until it is ready
  const std::vector<UprightSample>& design() const { return samples_; }
  // the state's difference from the reference at the last balancing tick (design coordinates)
  const UprightStateError& last_error() const { return error_; }

 private:
  // the design, once this much robot time has passed since the command (waits for it then)
  bool design_ready(double waited_s);
  void begin_crouch(const RobotState& state);
  void joint_ramp(const JointArray<double>& from, const JointArray<double>& to, double share,
                  JointCommand& command) const;
  // the two family members around progress s in 0..1, and the share of the way to the second
  struct Bracket {
    const UprightSample& a;
    const UprightSample& b;
    double w;
  };
  Bracket bracket(double s) const;
  // the reference pose at progress s: interpolated position, the orientation by slerp
  void reference_at(double s, UprightPosition& position) const;
  void balance(const RobotState& state, double s, double s_rate_per_s, JointCommand& command);
  double total_s() const;

  TwoLegStandConfig config_;
  std::future<std::vector<UprightSample>> pending_;
  std::vector<UprightSample> samples_;
  std::string design_error_;
  QpStand stand_;
  TwoLegPhase phase_ = TwoLegPhase::Idle;
  double phase_start_s_ = 0.0;
  double last_elapsed_s_ = 0.0;  // in the current phase, at the last tick
  bool lifting_ = false;         // the restand's second goal (the stand's height) is set
  double hold_s_ = 0.0;
  double heading_yaw_rad_ = 0.0;
  double stand_height_m_ = 0.0;
  double front_ahead_m_ = 0.0;
  JointArray<double> stand_q_{};   // the joints it stood on
  JointArray<double> crouch_q_{};  // the crouch: s = 0's hind legs, the front feet on the ground
  JointArray<double> phase_q_{};   // the joints when the current phase began
  // per tick, no allocation: the interpolated reference now and a tick later, its torque and gain
  UprightPosition reference_;
  UprightPosition reference_next_;
  UprightGain gain_;
  UprightStateError error_ = UprightStateError::Zero();
  Eigen::Matrix<double, kNumJoints, 1> feedback_ = Eigen::Matrix<double, kNumJoints, 1>::Zero();
};

}  // namespace cerebellum
