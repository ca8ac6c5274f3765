#include "lowlevel/shm/shm_lowlevel_source.hpp"

#include <stdexcept>

#include "safety/damping_command.hpp"

namespace cerebellum {
namespace {

int checked_timeout(int command_timeout_cycles) {
  if (command_timeout_cycles < 1) throw std::invalid_argument("shm: command_timeout_cycles must be >= 1");
  return command_timeout_cycles;
}

std::uint64_t load(const std::atomic<std::uint64_t>& counter) { return counter.load(std::memory_order_relaxed); }

}  // namespace

ShmLowLevelSource::ShmLowLevelSource(ShmLink& link, int command_timeout_cycles, const GuardLimits& limits)
    : link_(link),
      command_timeout_cycles_(checked_timeout(command_timeout_cycles)),
      command_limits_(limits.command),
      damping_kd_(limits.damping_kd) {
  active_ = damping_command(damping_kd_);
}

bool ShmLowLevelSource::run_cycle(const SensorFrame& frame, JointCommand& command) {
  last_time_s_ = frame.time_s;
  take_command(frame);
  link_.publish_state(frame);
  bump(cycles_);
  if (!latched_) return false;
  command = active_;
  return true;
}

void ShmLowLevelSource::take_command(const SensorFrame& frame) {
  if (!link_.take_command(received_)) {
    note_missed_cycle(frame);
    return;
  }
  // a frame that breaks the rules is a client bug: rejected whole, the last valid frame stays
  const ShmCommandCheck check = check_shm_command(received_, command_limits_);
  if (!check.ok()) {
    bump(frames_rejected_);
    ShmEvent event;
    event.kind = ShmEventKind::FrameRejected;
    event.time_s = frame.time_s;
    event.check = check;
    link_.report(event);
    note_missed_cycle(frame);
    return;
  }
  bump(frames_taken_);
  if (timed_out_) {
    timed_out_ = false;
    ShmEvent event;
    event.kind = ShmEventKind::CommandResumed;
    event.time_s = frame.time_s;
    link_.report(event);
  }
  active_ = received_;
  command_active_ = true;
  missed_in_row_ = 0;
}

void ShmLowLevelSource::note_missed_cycle(const SensorFrame& frame) {
  if (!command_active_) return;
  bump(missed_cycles_);
  // the last frame repeats until the client has been silent for the whole timeout
  if (++missed_in_row_ < command_timeout_cycles_) return;
  command_active_ = false;
  timed_out_ = true;
  refusal_reported_ = false;
  // the motors brake the joints and the robot sinks down
  active_ = damping_command(damping_kd_, frame.q);
  bump(command_timeouts_);
  ShmEvent event;
  event.kind = ShmEventKind::CommandTimedOut;
  event.time_s = frame.time_s;
  event.missed_cycles = missed_in_row_;
  event.damping_kd = damping_kd_;
  link_.report(event);
}

void ShmLowLevelSource::on_latched(const RobotState& state) {
  latched_ = true;
  ShmEvent event;
  event.kind = ShmEventKind::Latched;
  event.time_s = state.time_s;
  link_.report(event);
}

void ShmLowLevelSource::on_refused(const char* holder) {
  bump(refusals_);
  if (refusal_reported_) return;
  refusal_reported_ = true;
  ShmEvent event;
  event.kind = ShmEventKind::Refused;
  event.time_s = last_time_s_;
  event.holder = holder;
  link_.report(event);
}

void ShmLowLevelSource::compute(const RobotState&, JointCommand& command) { command = active_; }

ShmLowLevelCounters ShmLowLevelSource::counters() const {
  ShmLowLevelCounters c;
  c.cycles = load(cycles_);
  c.frames_taken = load(frames_taken_);
  c.frames_rejected = load(frames_rejected_);
  c.missed_cycles = load(missed_cycles_);
  c.command_timeouts = load(command_timeouts_);
  c.refusals = load(refusals_);
  return c;
}

}  // namespace cerebellum
