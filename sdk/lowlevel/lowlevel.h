/*
 * lowlevel.h: the shared-memory low-level motor interface of a CyberDog2-class robot.
 *
 * A daemon that owns the motors (here: the cerebellum MC) updates two POSIX shared-memory objects
 * every 1 ms; a controller program maps them, writes joint commands and reads joint states and
 * the IMU. The layout is ABI-compatible with the vendor's header of the same name (all structs
 * packed, little-endian, LP64); the asserts at the end of this file pin every size and offset.
 *
 * Handshake (see docs/shm-lowlevel.md):
 *   command: write cmd.legs, then set cmd.consumer_flags[CONSUMER_CONTROL] = 1; the daemon applies
 *            the frame and clears the flag; without new frames it repeats the last one, and after
 *            about 10 missed cycles it drops the command (the motors go to damping).
 *   state:   the daemon writes state.legs and the IMU, then sets state.consumer_flags[0..1] = 1;
 *            the motion controller reads and clears [CONSUMER_CONTROL], other modules use
 *            [CONSUMER_OTHER]. A flag that stays zero means the daemon is not updating.
 * Joint values follow the SDK/URDF convention: right-hand rule about each joint axis, zero = leg
 * straight down; no sign flip. Legs are ordered FRONT_RIGHT, FRONT_LEFT, BACK_RIGHT, BACK_LEFT.
 * lowlevel_sync.h adds fenced read and write helpers that never see a torn frame.
 */
#ifndef CEREBELLUM_SDK_LOWLEVEL_H
#define CEREBELLUM_SDK_LOWLEVEL_H

#include <errno.h>
#include <fcntl.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#ifdef __cplusplus
extern "C" {
#endif

#define LOWLEVEL_SPLINE_SHM_NAME "/spline_shm"
#define LOWLEVEL_SPLINE_SHM_SIZE 10240
#define LOWLEVEL_IMU_SHM_NAME "/imu_shm"
#define LOWLEVEL_IMU_SHM_SIZE 1024

/* who reads a state flag / who sets a command flag */
typedef enum lowlevel_consumer_def {
  CONSUMER_CONTROL = 0, /* the motion controller */
  CONSUMER_OTHER = 1,   /* any other module */
  CONSUMER_MAX = 2
} lowlevel_consumer_t;

/* index into legs[] */
typedef enum lowlevel_leg_def { FRONT_RIGHT = 0, FRONT_LEFT = 1, BACK_RIGHT = 2, BACK_LEFT = 3 } lowlevel_leg_t;

/* one motor's command: tau = t_ff + kp (p_des - p) + kd (v_des - v) */
typedef struct __attribute__((packed)) joint_control_def {
  float p_des; /* rad */
  float v_des; /* rad/s */
  float kp;    /* N m / rad */
  float kd;    /* N m s / rad */
  float t_ff;  /* N m */
} joint_control_t;

typedef struct __attribute__((packed)) leg_control_def {
  joint_control_t abad;
  joint_control_t hip;
  joint_control_t knee;
  joint_control_t foot; /* unused on a 12-joint robot */
  int32_t flags;        /* always 1 */
} leg_control_t;

typedef struct __attribute__((packed)) spline_cmd_data_def {
  leg_control_t legs[4];
  uint32_t consumer_flags[CONSUMER_MAX];
} spline_cmd_data_t;

/* joint_state_t.flags bits */
#define JOINT_STATE_ENABLED (1u << 0)
#define JOINT_STATE_OVER_VOLTAGE (1u << 1)
#define JOINT_STATE_OVER_CURRENT (1u << 2)
#define JOINT_STATE_OVER_TEMPERATURE (1u << 3)
#define JOINT_STATE_OVER_SPEED (1u << 4)
#define JOINT_STATE_ENCODER_FAULT (1u << 5)
#define JOINT_STATE_TEMPERATURE_SHIFT 8 /* bits 8..15: temperature + 40 (-40..215 deg C) */
#define JOINT_STATE_TEMPERATURE_OFFSET_C 40
#define JOINT_STATE_BUS_VOLTAGE_SHIFT 16 /* bits 16..23: bus voltage (V) */

typedef struct __attribute__((packed)) joint_state_def {
  int32_t flags;
  float p; /* rad */
  float v; /* rad/s */
  float t; /* N m */
} joint_state_t;

typedef struct __attribute__((packed)) leg_state_def {
  joint_state_t abad;
  joint_state_t hip;
  joint_state_t knee;
  joint_state_t foot; /* unused on a 12-joint robot: all zero */
} leg_state_t;

typedef struct __attribute__((packed)) spline_state_data_def {
  leg_state_t legs[4];
  uint32_t consumer_flags[CONSUMER_MAX];
} spline_state_data_t;

/* the content of LOWLEVEL_SPLINE_SHM_NAME */
typedef struct __attribute__((packed)) spline_data_def {
  spline_cmd_data_t cmd;
  spline_state_data_t state;
} spline_data_t, *spline_data_p;

/* the content of LOWLEVEL_IMU_SHM_NAME */
typedef struct __attribute__((packed)) nav_imu_def {
  size_t timestamp; /* ns */
  float acc[3];     /* m/s^2, body frame, includes gravity */
  float gyro[3];    /* rad/s, body frame */
  float q[4];       /* w, x, y, z; body to world, rotation order zyx */
} nav_imu_t, *nav_imu_p;

/* opens (creating if absent) and maps a shared-memory object; exits the program on failure,
   saying why (the vendor's header exits with perror alone) */
static inline void* lowlevel_map_shm(const char* name, size_t size) {
  int fd = shm_open(name, O_CREAT | O_RDWR, 0666);
  if (fd < 0) {
    int error = errno;
    fprintf(stderr, "lowlevel.h: cannot open the shared memory %s: %s%s\n", name, strerror(error),
            error == EACCES ? " (the MC creates it for its own user and group: run this program as that user or in "
                              "that group; cerebellum's shm.mode and shm.group say which)"
                            : "");
    exit(1);
  }
  if (ftruncate(fd, (off_t)size) != 0) {
    perror("ftruncate");
    exit(1);
  }
  void* memory = mmap(NULL, size, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  if (memory == MAP_FAILED) {
    perror("mmap");
    exit(1);
  }
  close(fd);
  return memory;
}

/* named variants: for a daemon started with a name prefix (several instances on one host) */
static inline spline_data_p create_spline_shm_named(const char* name) {
  return (spline_data_p)lowlevel_map_shm(name, LOWLEVEL_SPLINE_SHM_SIZE);
}

static inline nav_imu_p create_imu_shm_named(const char* name) {
  return (nav_imu_p)lowlevel_map_shm(name, LOWLEVEL_IMU_SHM_SIZE);
}

static inline spline_data_p create_spline_shm(void) { return create_spline_shm_named(LOWLEVEL_SPLINE_SHM_NAME); }

/* nothing to do: the mapping lives until the process exits */
static inline void destroy_spline_shm(spline_data_p ptr) { (void)ptr; }

static inline nav_imu_p create_imu_shm(void) { return create_imu_shm_named(LOWLEVEL_IMU_SHM_NAME); }

static inline void destroy_imu_shm(nav_imu_p ptr) { (void)ptr; }

/* the ABI, checked at every compile */
#ifdef __cplusplus
#define LOWLEVEL_STATIC_ASSERT(condition, message) static_assert(condition, message)
#else
#define LOWLEVEL_STATIC_ASSERT(condition, message) _Static_assert(condition, message)
#endif

LOWLEVEL_STATIC_ASSERT(sizeof(joint_control_t) == 20, "joint_control_t size");
LOWLEVEL_STATIC_ASSERT(offsetof(joint_control_t, p_des) == 0, "joint_control_t.p_des");
LOWLEVEL_STATIC_ASSERT(offsetof(joint_control_t, v_des) == 4, "joint_control_t.v_des");
LOWLEVEL_STATIC_ASSERT(offsetof(joint_control_t, kp) == 8, "joint_control_t.kp");
LOWLEVEL_STATIC_ASSERT(offsetof(joint_control_t, kd) == 12, "joint_control_t.kd");
LOWLEVEL_STATIC_ASSERT(offsetof(joint_control_t, t_ff) == 16, "joint_control_t.t_ff");
LOWLEVEL_STATIC_ASSERT(sizeof(leg_control_t) == 84, "leg_control_t size");
LOWLEVEL_STATIC_ASSERT(offsetof(leg_control_t, abad) == 0, "leg_control_t.abad");
LOWLEVEL_STATIC_ASSERT(offsetof(leg_control_t, hip) == 20, "leg_control_t.hip");
LOWLEVEL_STATIC_ASSERT(offsetof(leg_control_t, knee) == 40, "leg_control_t.knee");
LOWLEVEL_STATIC_ASSERT(offsetof(leg_control_t, foot) == 60, "leg_control_t.foot");
LOWLEVEL_STATIC_ASSERT(offsetof(leg_control_t, flags) == 80, "leg_control_t.flags");
LOWLEVEL_STATIC_ASSERT(sizeof(spline_cmd_data_t) == 344, "spline_cmd_data_t size");
LOWLEVEL_STATIC_ASSERT(offsetof(spline_cmd_data_t, legs) == 0, "spline_cmd_data_t.legs");
LOWLEVEL_STATIC_ASSERT(offsetof(spline_cmd_data_t, consumer_flags) == 336, "spline_cmd_data_t.consumer_flags");
LOWLEVEL_STATIC_ASSERT(sizeof(joint_state_t) == 16, "joint_state_t size");
LOWLEVEL_STATIC_ASSERT(offsetof(joint_state_t, flags) == 0, "joint_state_t.flags");
LOWLEVEL_STATIC_ASSERT(offsetof(joint_state_t, p) == 4, "joint_state_t.p");
LOWLEVEL_STATIC_ASSERT(offsetof(joint_state_t, v) == 8, "joint_state_t.v");
LOWLEVEL_STATIC_ASSERT(offsetof(joint_state_t, t) == 12, "joint_state_t.t");
LOWLEVEL_STATIC_ASSERT(sizeof(leg_state_t) == 64, "leg_state_t size");
LOWLEVEL_STATIC_ASSERT(offsetof(leg_state_t, abad) == 0, "leg_state_t.abad");
LOWLEVEL_STATIC_ASSERT(offsetof(leg_state_t, hip) == 16, "leg_state_t.hip");
LOWLEVEL_STATIC_ASSERT(offsetof(leg_state_t, knee) == 32, "leg_state_t.knee");
LOWLEVEL_STATIC_ASSERT(offsetof(leg_state_t, foot) == 48, "leg_state_t.foot");
LOWLEVEL_STATIC_ASSERT(sizeof(spline_state_data_t) == 264, "spline_state_data_t size");
LOWLEVEL_STATIC_ASSERT(offsetof(spline_state_data_t, legs) == 0, "spline_state_data_t.legs");
LOWLEVEL_STATIC_ASSERT(offsetof(spline_state_data_t, consumer_flags) == 256, "spline_state_data_t.consumer_flags");
LOWLEVEL_STATIC_ASSERT(sizeof(spline_data_t) == 608, "spline_data_t size");
LOWLEVEL_STATIC_ASSERT(offsetof(spline_data_t, cmd) == 0, "spline_data_t.cmd");
LOWLEVEL_STATIC_ASSERT(offsetof(spline_data_t, state) == 344, "spline_data_t.state");
LOWLEVEL_STATIC_ASSERT(sizeof(nav_imu_t) == 48, "nav_imu_t size");
LOWLEVEL_STATIC_ASSERT(offsetof(nav_imu_t, timestamp) == 0, "nav_imu_t.timestamp");
LOWLEVEL_STATIC_ASSERT(offsetof(nav_imu_t, acc) == 8, "nav_imu_t.acc");
LOWLEVEL_STATIC_ASSERT(offsetof(nav_imu_t, gyro) == 20, "nav_imu_t.gyro");
LOWLEVEL_STATIC_ASSERT(offsetof(nav_imu_t, q) == 32, "nav_imu_t.q");
LOWLEVEL_STATIC_ASSERT(sizeof(spline_data_t) <= LOWLEVEL_SPLINE_SHM_SIZE, "spline_data_t fits its object");
LOWLEVEL_STATIC_ASSERT(sizeof(nav_imu_t) <= LOWLEVEL_IMU_SHM_SIZE, "nav_imu_t fits its object");

#ifdef __cplusplus
}
#endif

#endif /* CEREBELLUM_SDK_LOWLEVEL_H */
