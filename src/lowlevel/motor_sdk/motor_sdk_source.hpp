// The MC side of the CyberDog2 low-level motor SDK, without sockets: frames come in through a
// mailbox stamped with robot time, the source applies the MC's rules (cyberdog2-lowlevel.md
// section 5) and, once the arbiter has latched it, commands the motors every tick.
//
// Chosen variants (docs/motor-sdk.md explains why):
// - bit0 (late > 10 ms): qd_des, tau_des and the position error to the measured angle are all
//   scaled by 10 ms / gap (the document's "position and torque decay", towards the measured angle)
// - bit1 (lost > 500 ms, and on entry): kd 4 damping for 2.5 s, then limp (the firmware's
//   variant); cleared by an all-zero frame that follows the previous frame within 500 ms, once
//   bit1 has been set for 2 s
// - bits 2-4: every tick, each stiff joint's executed q_des is kept within 8 / 10 / 12 deg of the
//   measured angle (the firmware's variant). Measured between adjacent frames (the document's
//   words) a one-frame jump to a far pose is only delayed by a few ticks and throws the robot
#pragma once

#include <atomic>
#include <cstdint>

#include "modes/source_arbiter.hpp"
#include "lowlevel/motor_sdk/motor_sdk_mailbox.hpp"
#include "lowlevel/motor_sdk/motor_sdk_parameters.hpp"

namespace cerebellum {

// what motor_ctrl_state reports; owned by the loop thread
struct MotorSdkStatus {
  bool motor_mode = false;  // latched by the arbiter (mode 15)
  std::uint16_t err_flag = kMotorSdkCommandLost;
  double ctrl_topic_interval_ms = 0.0;  // robot time between the last two frames
};

// running totals, readable from any thread
struct MotorSdkCounters {
  std::uint64_t frames_accepted = 0;            // entered the mailbox
  std::uint64_t frames_non_finite = 0;          // rejected: NaN/Inf
  std::uint64_t frames_dropped = 0;             // rejected: mailbox full
  std::uint64_t frames_refused = 0;             // arrived while another source or the MC's state held the robot
  std::uint64_t frames_ignored_while_lost = 0;  // non-zero frames while bit1 was set
  std::uint64_t commands_lost = 0;              // times bit1 was raised by a timeout
  std::uint64_t clamped_gains = 0;              // joint-frames with kp or kd clamped
  std::uint64_t clamped_velocities = 0;
  std::uint64_t clamped_torques = 0;
  std::uint64_t clamped_positions = 0;  // q_des pulled inside the joint limits
  std::uint64_t clamped_jumps = 0;      // joint-ticks with q_des pulled towards the measured angle (bits 2-4)
};

class MotorSdkSource final : public LowLevelSource {
 public:
  explicit MotorSdkSource(const MotorSdkParameters& parameters);

  // the receiving thread pushes frames here
  MotorSdkMailbox& mailbox() { return mailbox_; }

  const char* name() const override { return "the motor SDK"; }
  bool wants_control() const override { return mailbox_.has_pending(); }
  void on_latched(const RobotState& state) override;
  void on_refused(const char* holder) override;
  void compute(const RobotState& state, JointCommand& command) override;

  // loop thread only (observers run there)
  const MotorSdkStatus& status() const { return status_; }
  // any thread
  MotorSdkCounters counters() const;
  // who held the robot at the last refusal, nullptr before any
  const char* last_refusal_holder() const { return refusal_holder_.load(std::memory_order_relaxed); }
  const MotorSdkParameters& parameters() const { return parameters_; }

 private:
  void take_frame(const StampedFrame& frame);
  void raise_lost(double now_s);
  void set_err_bits(std::uint16_t bits, bool on);
  static void bump(std::atomic<std::uint64_t>& counter, std::uint64_t amount = 1) {
    counter.fetch_add(amount, std::memory_order_relaxed);
  }

  MotorSdkParameters parameters_;
  MotorSdkMailbox mailbox_;
  MotorSdkStatus status_;
  JointCommand active_{};  // the last accepted frame after the clamps (SDK convention)
  bool has_frame_ = false;
  double last_frame_s_ = 0.0;  // robot time of the newest frame
  double lost_since_s_ = 0.0;  // robot time bit1 was raised
  std::atomic<const char*> refusal_holder_{nullptr};
  std::atomic<std::uint64_t> refused_{0};
  std::atomic<std::uint64_t> ignored_while_lost_{0};
  std::atomic<std::uint64_t> commands_lost_{0};
  std::atomic<std::uint64_t> clamped_gains_{0};
  std::atomic<std::uint64_t> clamped_velocities_{0};
  std::atomic<std::uint64_t> clamped_torques_{0};
  std::atomic<std::uint64_t> clamped_positions_{0};
  std::atomic<std::uint64_t> clamped_jumps_{0};
};

}  // namespace cerebellum
