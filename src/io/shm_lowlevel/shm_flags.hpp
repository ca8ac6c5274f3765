// The lowlevel.h objects' handshake words as C++ atomics: the state's consumer flags, the command's
// flag and the IMU's timestamp, where the SDK's lowlevel_sync.h (their one home, used by C
// clients) places them. For the MC as the daemon (ShmLowLevelPort); the MC as a daemon's client
// (io/shm_lowlevel_robot) calls lowlevel_sync.h's reads and writes themselves.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>

#include "lowlevel/lowlevel_sync.h"

namespace cerebellum {

inline std::atomic_ref<std::uint32_t> shm_state_flag(spline_data_t* spline, std::size_t consumer) {
  return std::atomic_ref<std::uint32_t>(*lowlevel_state_flag(spline, static_cast<lowlevel_consumer_t>(consumer)));
}

inline std::atomic_ref<std::uint32_t> shm_command_flag(spline_data_t* spline) {
  return std::atomic_ref<std::uint32_t>(*lowlevel_command_flag(spline));
}

inline std::atomic_ref<std::size_t> shm_imu_timestamp(nav_imu_t* imu) {
  return std::atomic_ref<std::size_t>(*lowlevel_imu_timestamp(imu));
}

}  // namespace cerebellum
