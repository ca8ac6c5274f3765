/* lowlevel.h compiled by a C11 compiler: the layout asserts hold there too, and the fields land
   on the byte offsets of the reference table when written through the structs. */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <string.h>

#include "lowlevel/lowlevel.h"
#include "lowlevel/lowlevel_sync.h"

/* offsets from the table, written out by hand */
_Static_assert(offsetof(spline_data_t, cmd.legs[1].hip.kp) == 84 + 20 + 8, "cmd leg 1 hip kp");
_Static_assert(offsetof(spline_data_t, cmd.legs[3].flags) == 3 * 84 + 80, "cmd leg 3 flags");
_Static_assert(offsetof(spline_data_t, cmd.consumer_flags[1]) == 336 + 4, "cmd flag 1");
_Static_assert(offsetof(spline_data_t, state.legs[2].knee.t) == 344 + 2 * 64 + 32 + 12, "state leg 2 knee t");
_Static_assert(offsetof(spline_data_t, state.consumer_flags[0]) == 344 + 256, "state flag 0");
_Static_assert(offsetof(nav_imu_t, q[3]) == 32 + 12, "imu q z");
_Static_assert(CONSUMER_CONTROL == 0 && CONSUMER_OTHER == 1 && CONSUMER_MAX == 2, "consumer enum");
_Static_assert(FRONT_RIGHT == 0 && FRONT_LEFT == 1 && BACK_RIGHT == 2 && BACK_LEFT == 3, "leg enum");

static int failures = 0;

static void expect_at(const unsigned char* base, size_t offset, const void* value, size_t size, const char* what) {
  if (memcmp(base + offset, value, size) != 0) {
    fprintf(stderr, "FAIL: %s not at byte %zu\n", what, offset);
    ++failures;
  }
}

int main(void) {
  static spline_data_t data;
  static nav_imu_t imu;
  memset(&data, 0, sizeof data);
  memset(&imu, 0, sizeof imu);
  const float kp = 12.5f;
  const int32_t flags = 0x00184101;
  const uint32_t consumer = 7u;
  const float knee_t = -3.25f;
  const size_t stamp = 123456789u;
  const float qz = 0.75f;
  data.cmd.legs[FRONT_LEFT].hip.kp = kp;
  data.cmd.legs[BACK_LEFT].flags = flags;
  data.cmd.consumer_flags[CONSUMER_OTHER] = consumer;
  data.state.legs[BACK_RIGHT].knee.t = knee_t;
  data.state.consumer_flags[CONSUMER_CONTROL] = consumer;
  imu.timestamp = stamp;
  imu.q[3] = qz;
  const unsigned char* bytes = (const unsigned char*)&data;
  expect_at(bytes, 112, &kp, sizeof kp, "cmd.legs[1].hip.kp");
  expect_at(bytes, 332, &flags, sizeof flags, "cmd.legs[3].flags");
  expect_at(bytes, 340, &consumer, sizeof consumer, "cmd.consumer_flags[1]");
  expect_at(bytes, 516, &knee_t, sizeof knee_t, "state.legs[2].knee.t");
  expect_at(bytes, 600, &consumer, sizeof consumer, "state.consumer_flags[0]");
  expect_at((const unsigned char*)&imu, 0, &stamp, sizeof stamp, "imu.timestamp");
  expect_at((const unsigned char*)&imu, 44, &qz, sizeof qz, "imu.q[3]");
  /* the sync helpers address the same bytes */
  if ((uintptr_t)lowlevel_state_flag(&data, CONSUMER_CONTROL) != (uintptr_t)(bytes + 600) ||
      (uintptr_t)lowlevel_command_flag(&data) != (uintptr_t)(bytes + 336) ||
      (uintptr_t)lowlevel_imu_timestamp(&imu) != (uintptr_t)&imu) {
    fprintf(stderr, "FAIL: sync helper addresses\n");
    ++failures;
  }
  if (failures == 0) printf("lowlevel.h layout from C: ok\n");
  return failures == 0 ? 0 : 1;
}
