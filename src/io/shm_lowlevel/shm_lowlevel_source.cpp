#include "io/shm_lowlevel/shm_lowlevel_source.hpp"

#include <cstddef>
#include <cstring>
#include <stdexcept>

#include "safety/damping_command.hpp"

namespace cerebellum {
namespace {

constexpr std::size_t kStateFlagsOffset =
    offsetof(spline_data_t, state) + offsetof(spline_state_data_t, consumer_flags);
constexpr std::size_t kCommandFlagOffset = offsetof(spline_data_t, cmd) + offsetof(spline_cmd_data_t, consumer_flags) +
                                           sizeof(std::uint32_t) * CONSUMER_CONTROL;
static_assert(kStateFlagsOffset % alignof(std::uint32_t) == 0 && kCommandFlagOffset % alignof(std::uint32_t) == 0);
static_assert(offsetof(nav_imu_t, timestamp) % alignof(std::size_t) == 0);

template <typename T>
std::atomic_ref<T> atomic_at(void* base, std::size_t offset_bytes) {
  return std::atomic_ref<T>(*reinterpret_cast<T*>(static_cast<char*>(base) + offset_bytes));
}

const ShmLowLevelConfig& checked(const ShmLowLevelConfig& config) {
  if (config.command_timeout_cycles < 1) throw std::invalid_argument("shm: command_timeout_cycles must be >= 1");
  return config;
}

}  // namespace

ShmLowLevelSource::ShmLowLevelSource(const ShmLowLevelConfig& config, const GuardLimits& limits, std::FILE* log)
    : config_(checked(config)),
      command_limits_(limits.command),
      damping_kd_(limits.damping_kd),
      spline_(shm_spline_object_name(config.name_prefix), LOWLEVEL_SPLINE_SHM_SIZE, config.mode, config.group_id),
      imu_(shm_imu_object_name(config.name_prefix), LOWLEVEL_IMU_SHM_SIZE, config.mode, config.group_id),
      log_(log),
      log_file_(log) {
  active_ = damping_command(damping_kd_);
  std::fprintf(log_file_, "cerebellum shm: serving %s and %s (mode %04o), 1 ms updates\n", spline_.name().c_str(),
               imu_.name().c_str(), config_.mode);
}

ShmLowLevelSource::~ShmLowLevelSource() {
  log_.flush();
  const ShmLowLevelCounters c = counters();
  std::fprintf(log_file_,
               "cerebellum shm: closing %s and %s: %llu cycles, %llu frames taken, %llu rejected, %llu command "
               "timeouts\n",
               spline_.name().c_str(), imu_.name().c_str(), static_cast<unsigned long long>(c.cycles),
               static_cast<unsigned long long>(c.frames_taken), static_cast<unsigned long long>(c.frames_rejected),
               static_cast<unsigned long long>(c.command_timeouts));
  std::fflush(log_file_);
}

std::atomic_ref<std::uint32_t> ShmLowLevelSource::state_flag(std::size_t consumer) const {
  return atomic_at<std::uint32_t>(spline(), kStateFlagsOffset + sizeof(std::uint32_t) * consumer);
}

std::atomic_ref<std::uint32_t> ShmLowLevelSource::command_flag() const {
  return atomic_at<std::uint32_t>(spline(), kCommandFlagOffset);
}

std::atomic_ref<std::size_t> ShmLowLevelSource::imu_timestamp() const {
  return atomic_at<std::size_t>(imu(), offsetof(nav_imu_t, timestamp));
}

bool ShmLowLevelSource::on_substep(const SensorFrame& frame, JointCommand& command) {
  last_time_s_ = frame.time_s;
  take_command(frame);
  publish_state(frame);
  counts_.cycles.add();
  if (!latched_) return false;
  command = active_;
  return true;
}

void ShmLowLevelSource::take_command(const SensorFrame& frame) {
  // the flag's acquire pairs with the client's release: its legs are complete
  if (command_flag().load(std::memory_order_acquire) == 0) {
    note_missed_cycle(frame);
    return;
  }
  std::memcpy(command_legs_, spline()->cmd.legs, sizeof(command_legs_));
  // the release orders the copy before the clear: a client that sees 0 may write the next frame
  command_flag().store(0, std::memory_order_release);

  const ShmCommandCheck check = decode_shm_command(command_legs_, command_limits_, decoded_);
  if (!check.ok()) {
    counts_.frames_rejected.add();
    ShmEvent event;
    event.kind = ShmEventKind::FrameRejected;
    event.time_s = frame.time_s;
    event.check = check;
    log_.post(event);
    note_missed_cycle(frame);
    return;
  }
  counts_.frames_taken.add();
  if (timed_out_) {
    timed_out_ = false;
    ShmEvent event;
    event.kind = ShmEventKind::CommandResumed;
    event.time_s = frame.time_s;
    log_.post(event);
  }
  active_ = decoded_;
  command_active_ = true;
  missed_in_row_ = 0;
}

void ShmLowLevelSource::note_missed_cycle(const SensorFrame& frame) {
  if (!command_active_) return;
  counts_.missed_cycles.add();
  // the last frame repeats until the client has been silent for the whole timeout
  if (++missed_in_row_ < config_.command_timeout_cycles) return;
  command_active_ = false;
  timed_out_ = true;
  refusal_reported_ = false;
  // the motors brake the joints and the robot sinks down
  active_ = damping_command(damping_kd_, frame.q);
  counts_.command_timeouts.add();
  ShmEvent event;
  event.kind = ShmEventKind::CommandTimedOut;
  event.time_s = frame.time_s;
  event.missed_cycles = missed_in_row_;
  event.damping_kd = damping_kd_;
  log_.post(event);
}

void ShmLowLevelSource::publish_state(const SensorFrame& frame) {
  encode_shm_legs(frame, state_legs_);
  encode_shm_imu(frame, imu_frame_);
  // a sequence lock with the flags as the "complete" mark and the IMU timestamp as the
  // generation: clear the flags, write the body, then the timestamp and the flags (release)
  state_flag(CONSUMER_CONTROL).store(0, std::memory_order_relaxed);
  state_flag(CONSUMER_OTHER).store(0, std::memory_order_relaxed);
  std::atomic_thread_fence(std::memory_order_release);
  std::memcpy(spline()->state.legs, state_legs_, sizeof(state_legs_));
  constexpr std::size_t kImuBodyOffset = offsetof(nav_imu_t, acc);
  std::memcpy(reinterpret_cast<char*>(imu()) + kImuBodyOffset,
              reinterpret_cast<const char*>(&imu_frame_) + kImuBodyOffset, sizeof(nav_imu_t) - kImuBodyOffset);
  imu_timestamp().store(imu_frame_.timestamp, std::memory_order_release);
  state_flag(CONSUMER_CONTROL).store(1, std::memory_order_release);
  state_flag(CONSUMER_OTHER).store(1, std::memory_order_release);
}

void ShmLowLevelSource::on_latched(const RobotState& state) {
  latched_ = true;
  ShmEvent event;
  event.kind = ShmEventKind::Latched;
  event.time_s = state.time_s;
  log_.post(event);
}

void ShmLowLevelSource::on_refused(const char* holder) {
  counts_.refusals.add();
  if (refusal_reported_) return;
  refusal_reported_ = true;
  ShmEvent event;
  event.kind = ShmEventKind::Refused;
  event.time_s = last_time_s_;
  event.holder = holder;
  log_.post(event);
}

void ShmLowLevelSource::compute(const RobotState&, JointCommand& command) { command = active_; }

ShmLowLevelCounters ShmLowLevelSource::counters() const { return counts_; }

}  // namespace cerebellum
