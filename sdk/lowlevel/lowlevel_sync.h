/*
 * lowlevel_sync.h: fenced access to the lowlevel.h shared memory from a controller program.
 *
 * lowlevel.h itself defines no memory ordering. The cerebellum daemon publishes each state frame
 * like a sequence lock: it clears state.consumer_flags[0..1], writes the legs and the IMU, stores
 * the new IMU timestamp (release) and sets the flags to 1 (release). A reader that copies the
 * frame and then finds its flag still set and the IMU timestamp unchanged holds one whole frame.
 * Commands go the other way: write the legs only after the daemon has cleared the command flag,
 * then set the flag with release order.
 */
#ifndef CEREBELLUM_SDK_LOWLEVEL_SYNC_H
#define CEREBELLUM_SDK_LOWLEVEL_SYNC_H

#include <string.h>

#include "lowlevel.h"

#ifdef __cplusplus
extern "C" {
#endif

/* the 32-bit flags and the 64-bit timestamp sit at naturally aligned offsets of page-aligned
   mappings (see lowlevel.h), so they can be accessed atomically */
static inline uint32_t* lowlevel_state_flag(spline_data_p shm, lowlevel_consumer_t consumer) {
  return (uint32_t*)((uintptr_t)shm + offsetof(spline_data_t, state) + offsetof(spline_state_data_t, consumer_flags) +
                     sizeof(uint32_t) * (size_t)consumer);
}

static inline uint32_t* lowlevel_command_flag(spline_data_p shm) {
  return (uint32_t*)((uintptr_t)shm + offsetof(spline_data_t, cmd) + offsetof(spline_cmd_data_t, consumer_flags) +
                     sizeof(uint32_t) * (size_t)CONSUMER_CONTROL);
}

static inline size_t* lowlevel_imu_timestamp(nav_imu_p imu) {
  const uintptr_t address = (uintptr_t)imu + offsetof(nav_imu_t, timestamp);
  return (size_t*)address;
}

/*
 * Copies the newest state frame into legs and imu_out and clears the consumer's flag.
 * Returns 1 when a whole frame published since the last successful call was copied; 0 when there
 * is nothing new yet, or when the daemon rewrote the frame during the copy (call again).
 */
static inline int lowlevel_read_state(spline_data_p shm, nav_imu_p imu, lowlevel_consumer_t consumer,
                                      leg_state_t legs[4], nav_imu_t* imu_out) {
  uint32_t* flag = lowlevel_state_flag(shm, consumer);
  size_t* stamp = lowlevel_imu_timestamp(imu);
  if (__atomic_load_n(flag, __ATOMIC_ACQUIRE) == 0) return 0;
  const size_t stamp_before = __atomic_load_n(stamp, __ATOMIC_ACQUIRE);
  memcpy(legs, (const void*)shm->state.legs, sizeof(shm->state.legs));
  memcpy(imu_out, (const void*)imu, sizeof(nav_imu_t));
  __atomic_thread_fence(__ATOMIC_ACQUIRE);
  /* a rewrite clears the flag first and ends with a new timestamp */
  if (__atomic_load_n(flag, __ATOMIC_RELAXED) == 0 || __atomic_load_n(stamp, __ATOMIC_RELAXED) != stamp_before) {
    return 0;
  }
  imu_out->timestamp = stamp_before;
  __atomic_store_n(flag, 0u, __ATOMIC_RELAXED);
  return 1;
}

/* 1 while the daemon has not yet taken the last command frame */
static inline int lowlevel_command_pending(spline_data_p shm) {
  return __atomic_load_n(lowlevel_command_flag(shm), __ATOMIC_ACQUIRE) != 0;
}

/*
 * Hands a command frame to the daemon. Returns 1 when written; 0 when the daemon has not yet
 * taken the previous frame (nothing written: overwriting it could tear the frame it is reading).
 */
static inline int lowlevel_write_command(spline_data_p shm, const leg_control_t legs[4]) {
  uint32_t* flag = lowlevel_command_flag(shm);
  if (__atomic_load_n(flag, __ATOMIC_ACQUIRE) != 0) return 0;
  memcpy((void*)shm->cmd.legs, legs, sizeof(shm->cmd.legs));
  __atomic_store_n(flag, 1u, __ATOMIC_RELEASE);
  return 1;
}

#ifdef __cplusplus
}
#endif

#endif /* CEREBELLUM_SDK_LOWLEVEL_SYNC_H */
