#include "lowlevel/motor_sdk/motor_sdk_source.hpp"

#include "lowlevel/motor_sdk/motor_sdk_frame_rules.hpp"
#include "safety/damping_command.hpp"

namespace cerebellum {
namespace {

constexpr std::uint16_t kJumpBits = kMotorSdkAbadJump | kMotorSdkHipJump | kMotorSdkKneeJump;
// robot time is a sum of float steps: thresholds are compared with this much slack, so a gap of
// exactly 500 ms of ticks counts as 500 ms
constexpr double kTimeToleranceS = 1e-9;

}  // namespace

MotorSdkSource::MotorSdkSource(const MotorSdkParameters& parameters) : parameters_(parameters) {}

MotorSdkCounters MotorSdkSource::counters() const {
  MotorSdkCounters c;
  c.frames_accepted = mailbox_.accepted();
  c.frames_non_finite = mailbox_.non_finite();
  c.frames_dropped = mailbox_.dropped();
  c.frames_refused = refused_.load(std::memory_order_relaxed);
  c.frames_ignored_while_lost = ignored_while_lost_.load(std::memory_order_relaxed);
  c.commands_lost = commands_lost_.load(std::memory_order_relaxed);
  c.clamped_gains = clamped_gains_.load(std::memory_order_relaxed);
  c.clamped_velocities = clamped_velocities_.load(std::memory_order_relaxed);
  c.clamped_torques = clamped_torques_.load(std::memory_order_relaxed);
  c.clamped_positions = clamped_positions_.load(std::memory_order_relaxed);
  c.clamped_jumps = clamped_jumps_.load(std::memory_order_relaxed);
  return c;
}

void MotorSdkSource::on_latched(const RobotState& state) {
  // motor mode starts in the communication-lost state: only all-zero frames activate it
  status_.motor_mode = true;
  last_frame_s_ = state.time_s;
  raise_lost(state.time_s);
}

void MotorSdkSource::on_refused(const char* holder) {
  std::uint64_t discarded = 0;
  while (mailbox_.pop()) ++discarded;
  bump(refused_, discarded);
  refusal_holder_.store(holder, std::memory_order_relaxed);
}

void MotorSdkSource::compute(const RobotState& state, JointCommand& command) {
  while (std::optional<StampedFrame> frame = mailbox_.pop()) take_frame(*frame);

  const double now_s = state.time_s;
  const double gap_s = now_s - last_frame_s_;
  const bool late = gap_s > parameters_.late_after_s + kTimeToleranceS;
  set_err_bits(kMotorSdkCommandLate, late);
  if ((status_.err_flag & kMotorSdkCommandLost) == 0 && gap_s > parameters_.lost_after_s + kTimeToleranceS) {
    raise_lost(now_s);
    bump(commands_lost_);
  }

  if (status_.err_flag & kMotorSdkCommandLost) {
    // damping lets the robot sink and lie down; limp once it has had time to
    const bool damping = now_s - lost_since_s_ < parameters_.lost_damping_duration_s - kTimeToleranceS;
    command = damping ? damping_command(parameters_.lost_damping_kd) : passive_command();
    return;
  }
  command = active_;
  if (late) decay_late_command(command, state.q, gap_s, parameters_);
  // the jump rule each tick against where the joints are (the firmware's variant): a stiff target
  // far away is approached a few degrees ahead of the joint instead of being executed at once
  set_err_bits(kJumpBits, false);
  if (parameters_.position_mutation_limit) {
    const JumpClampResult jumps = clamp_position_jumps(command, state.q, parameters_);
    set_err_bits(jumps.err_bits, true);
    bump(clamped_jumps_, jumps.joints);
  }
}

void MotorSdkSource::take_frame(const StampedFrame& stamped) {
  const double interval_s = has_frame_ ? stamped.received_s - last_frame_s_ : 0.0;
  status_.ctrl_topic_interval_ms = interval_s * 1000.0;
  const bool follows_closely = has_frame_ && interval_s <= parameters_.lost_after_s + kTimeToleranceS;
  has_frame_ = true;
  last_frame_s_ = stamped.received_s;
  JointCommand frame = stamped.command;

  if (status_.err_flag & kMotorSdkCommandLost) {
    // only a live stream of all-zero frames, after the robot has had time to lie down, clears it
    const bool lain_long_enough =
        stamped.received_s - lost_since_s_ >= parameters_.lie_before_clear_s - kTimeToleranceS;
    if (follows_closely && lain_long_enough && is_all_zero_frame(frame, parameters_.zero_tolerance)) {
      set_err_bits(kMotorSdkCommandLost, false);
      active_ = passive_command();
    } else if (!is_all_zero_frame(frame, parameters_.zero_tolerance)) {
      bump(ignored_while_lost_);
    }
    return;
  }

  const RangeClampCount clamped = clamp_to_ranges(frame, parameters_);
  bump(clamped_gains_, clamped.gains);
  bump(clamped_velocities_, clamped.velocities);
  bump(clamped_torques_, clamped.torques);
  bump(clamped_positions_, clamped.positions);

  active_ = frame;
}

void MotorSdkSource::raise_lost(double now_s) {
  status_.err_flag = static_cast<std::uint16_t>((status_.err_flag & ~kJumpBits) | kMotorSdkCommandLost);
  lost_since_s_ = now_s;
  active_ = passive_command();
}

void MotorSdkSource::set_err_bits(std::uint16_t bits, bool on) {
  status_.err_flag = static_cast<std::uint16_t>(on ? (status_.err_flag | bits) : (status_.err_flag & ~bits));
}

}  // namespace cerebellum
