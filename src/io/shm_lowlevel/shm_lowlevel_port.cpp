#include "io/shm_lowlevel/shm_lowlevel_port.hpp"

#include <cstddef>
#include <cstring>

#include "io/common/wall_clock.hpp"
#include "io/shm_lowlevel/shm_flags.hpp"

namespace cerebellum {

ShmLowLevelPort::ShmLowLevelPort(const ShmLowLevelConfig& config, const GuardLimits& limits, std::FILE* log)
    : mode_(config.mode),
      source_(*this, config.command_timeout_cycles, limits),
      spline_(shm_spline_object_name(config.name_prefix), LOWLEVEL_SPLINE_SHM_SIZE, config.mode, config.group_id),
      imu_(shm_imu_object_name(config.name_prefix), LOWLEVEL_IMU_SHM_SIZE, config.mode, config.group_id),
      log_(log),
      log_file_(log) {
  std::fprintf(log_file_, "cerebellum shm: serving %s and %s (mode %04o), 1 ms updates\n", spline_.name().c_str(),
               imu_.name().c_str(), mode_);
}

ShmLowLevelPort::~ShmLowLevelPort() {
  log_.flush();
  const ShmLowLevelCounters c = source_.counters();
  std::fprintf(log_file_,
               "cerebellum shm: closing %s and %s: %llu cycles, %llu frames taken, %llu rejected, %llu command "
               "timeouts\n",
               spline_.name().c_str(), imu_.name().c_str(), static_cast<unsigned long long>(c.cycles),
               static_cast<unsigned long long>(c.frames_taken), static_cast<unsigned long long>(c.frames_rejected),
               static_cast<unsigned long long>(c.command_timeouts));
  std::fflush(log_file_);
}

bool ShmLowLevelPort::on_substep(const SensorFrame& frame, JointCommand& command) {
  return source_.run_cycle(frame, command);
}

bool ShmLowLevelPort::take_command(JointCommand& command) {
  bool taken = false;
  // a frame reaches the decoder through the link's faults, when the simulation set any
  const LinkFaults::Deliver deliver = [this, &taken](const std::uint8_t* data, std::size_t size) {
    if (size != sizeof(command_legs_)) return;
    std::memcpy(command_legs_, data, size);
    taken = true;
  };
  const double now_s = wall_seconds();
  // the flag's acquire pairs with the client's release: its legs are complete
  if (shm_command_flag(spline()).load(std::memory_order_acquire) != 0) {
    leg_control_t legs[kNumLegs];
    std::memcpy(legs, spline()->cmd.legs, sizeof(legs));
    // the release orders the copy before the clear: a client that sees 0 may write the next frame
    shm_command_flag(spline()).store(0, std::memory_order_release);
    receive_through(link_faults_, reinterpret_cast<const std::uint8_t*>(legs), sizeof(legs), now_s, deliver);
  }
  release_due(link_faults_, now_s, deliver);
  if (!taken) return false;
  command = decode_shm_command(command_legs_);
  return true;
}

void ShmLowLevelPort::publish_state(const SensorFrame& frame) {
  encode_shm_legs(frame, state_legs_);
  encode_shm_imu(frame, imu_frame_);
  // a sequence lock with the flags as the "complete" mark and the IMU timestamp as the
  // generation: clear the flags, write the body, then the timestamp and the flags (release)
  shm_state_flag(spline(), CONSUMER_CONTROL).store(0, std::memory_order_relaxed);
  shm_state_flag(spline(), CONSUMER_OTHER).store(0, std::memory_order_relaxed);
  std::atomic_thread_fence(std::memory_order_release);
  std::memcpy(spline()->state.legs, state_legs_, sizeof(state_legs_));
  constexpr std::size_t kImuBodyOffset = offsetof(nav_imu_t, acc);
  std::memcpy(reinterpret_cast<char*>(imu()) + kImuBodyOffset,
              reinterpret_cast<const char*>(&imu_frame_) + kImuBodyOffset, sizeof(nav_imu_t) - kImuBodyOffset);
  shm_imu_timestamp(imu()).store(imu_frame_.timestamp, std::memory_order_release);
  shm_state_flag(spline(), CONSUMER_CONTROL).store(1, std::memory_order_release);
  shm_state_flag(spline(), CONSUMER_OTHER).store(1, std::memory_order_release);
}

}  // namespace cerebellum
