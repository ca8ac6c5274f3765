/*
 * example_stand: a low-level client of the shared-memory interface (lowlevel.h).
 * Waits for the daemon's state, then at 1 kHz moves every leg from its current pose to the lying
 * pose and on to the stand pose (SDK convention, kp 60, kd 2) and holds it; stops after
 * --duration seconds or on Ctrl-C / SIGTERM.
 *
 *   lowlevel_example_stand [--duration S] [--prefix P]
 *
 * The daemon must allow low-level control (cerebellum: mc.startup off or damper, shm.enabled).
 */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "lowlevel/lowlevel.h"
#include "lowlevel/lowlevel_sync.h"

#define PI 3.14159265358979323846
#define DEG(x) ((x)*PI / 180.0)
#define PERIOD_NS 1000000L
#define FOLD_S 1.0 /* current pose -> lying */
#define RISE_S 1.5 /* lying -> stand */
#define WAIT_FOR_STATE_S 10.0
#define STATE_LOST_S 1.0 /* no new state for this long: the daemon is gone */
#define KP 60.0f
#define KD 2.0f

static const double kLying[3] = {0.0, DEG(80.0), DEG(-135.0)};
static const double kStand[3] = {0.0, DEG(45.0), DEG(-70.0)};

struct options {
  double duration_s;
  const char* prefix;
};

static int parse_options(int argc, char** argv, struct options* options) {
  options->duration_s = 10.0;
  options->prefix = NULL;
  for (int i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "--duration") == 0 && i + 1 < argc) {
      char* end = NULL;
      options->duration_s = strtod(argv[++i], &end);
      if (*end != '\0' || !(options->duration_s > 0.0)) return 0;
    } else if (strcmp(argv[i], "--prefix") == 0 && i + 1 < argc) {
      options->prefix = argv[++i];
    } else {
      return 0;
    }
  }
  return 1;
}

static double seconds_between(const struct timespec* from, const struct timespec* to) {
  return (double)(to->tv_sec - from->tv_sec) + 1e-9 * (double)(to->tv_nsec - from->tv_nsec);
}

static void add_ns(struct timespec* t, long ns) {
  t->tv_nsec += ns;
  while (t->tv_nsec >= 1000000000L) {
    t->tv_nsec -= 1000000000L;
    t->tv_sec += 1;
  }
}

/* smooth 0..1 ramp with zero slope at both ends */
static double smooth_step(double fraction) {
  const double s = fraction < 0.0 ? 0.0 : fraction > 1.0 ? 1.0 : fraction;
  return 0.5 - 0.5 * cos(PI * s);
}

static joint_control_t* joint_of(leg_control_t* leg, int joint) {
  return joint == 0 ? &leg->abad : joint == 1 ? &leg->hip : &leg->knee;
}

static float position_of(const leg_state_t* leg, int joint) {
  return joint == 0 ? leg->abad.p : joint == 1 ? leg->hip.p : leg->knee.p;
}

/* the stand-up trajectory at elapsed_s, starting from start[leg][joint] */
static void stand_command(double elapsed_s, double start[4][3], leg_control_t legs[4]) {
  const int folding = elapsed_s < FOLD_S;
  const double fraction = folding ? smooth_step(elapsed_s / FOLD_S) : smooth_step((elapsed_s - FOLD_S) / RISE_S);
  memset(legs, 0, 4 * sizeof(leg_control_t));
  for (int leg = 0; leg < 4; ++leg) {
    for (int joint = 0; joint < 3; ++joint) {
      const double from = folding ? start[leg][joint] : kLying[joint];
      const double to = folding ? kLying[joint] : kStand[joint];
      joint_control_t* out = joint_of(&legs[leg], joint);
      out->p_des = (float)(from + (to - from) * fraction);
      out->kp = KP;
      out->kd = KD;
    }
    legs[leg].flags = 1;
  }
}

/* SIGINT and SIGTERM stay blocked and are polled each cycle: no handler, no shared flag */
static int stop_requested(void) {
  sigset_t pending;
  sigpending(&pending);
  return sigismember(&pending, SIGINT) || sigismember(&pending, SIGTERM);
}

int main(int argc, char** argv) {
  struct options options;
  if (!parse_options(argc, argv, &options)) {
    fprintf(stderr, "usage: %s [--duration S] [--prefix P]\n", argv[0]);
    return 2;
  }
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  sigprocmask(SIG_BLOCK, &stop_signals, NULL);

  spline_data_p shm;
  nav_imu_p imu;
  if (options.prefix == NULL) {
    shm = create_spline_shm();
    imu = create_imu_shm();
  } else {
    char spline_name[128];
    char imu_name[128];
    snprintf(spline_name, sizeof spline_name, "/%sspline_shm", options.prefix);
    snprintf(imu_name, sizeof imu_name, "/%simu_shm", options.prefix);
    shm = create_spline_shm_named(spline_name);
    imu = create_imu_shm_named(imu_name);
  }

  /* wait for the daemon's first state frame: it gives the starting pose */
  leg_state_t state[4];
  nav_imu_t imu_frame;
  struct timespec start;
  struct timespec now;
  clock_gettime(CLOCK_MONOTONIC, &start);
  while (!lowlevel_read_state(shm, imu, CONSUMER_CONTROL, state, &imu_frame)) {
    clock_gettime(CLOCK_MONOTONIC, &now);
    if (stop_requested()) return 0;
    if (seconds_between(&start, &now) > WAIT_FOR_STATE_S) {
      fprintf(stderr, "example_stand: no state from the daemon after %.0f s (is it running with shm enabled?)\n",
              WAIT_FOR_STATE_S);
      return 1;
    }
    const struct timespec pause = {0, PERIOD_NS};
    nanosleep(&pause, NULL);
  }
  double start_pose[4][3];
  for (int leg = 0; leg < 4; ++leg) {
    for (int joint = 0; joint < 3; ++joint) start_pose[leg][joint] = position_of(&state[leg], joint);
  }
  printf("example_stand: state received (t=%.3f s), standing up\n", 1e-9 * (double)imu_frame.timestamp);
  fflush(stdout);

  /* 1 kHz on absolute deadlines */
  unsigned long written = 0;
  unsigned long busy = 0;
  unsigned long states = 1;
  int status = 0;
  leg_control_t command[4];
  clock_gettime(CLOCK_MONOTONIC, &start);
  struct timespec deadline = start;
  struct timespec last_state = start;
  for (;;) {
    add_ns(&deadline, PERIOD_NS);
    clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &deadline, NULL);
    clock_gettime(CLOCK_MONOTONIC, &now);
    if (seconds_between(&deadline, &now) > 0.01) deadline = now; /* far behind: skip, do not burst */
    if (stop_requested()) break;
    const double elapsed_s = seconds_between(&start, &now);
    if (elapsed_s >= options.duration_s) break;

    if (lowlevel_read_state(shm, imu, CONSUMER_CONTROL, state, &imu_frame)) {
      ++states;
      last_state = now;
    } else if (seconds_between(&last_state, &now) > STATE_LOST_S) {
      fprintf(stderr, "example_stand: no state for %.1f s: the daemon stopped\n", STATE_LOST_S);
      status = 1;
      break;
    }
    stand_command(elapsed_s, start_pose, command);
    if (lowlevel_write_command(shm, command)) {
      ++written;
    } else {
      ++busy; /* the daemon has not taken the previous frame yet */
    }
  }
  printf("example_stand: done: %lu commands written, %lu cycles with the previous one still pending, %lu states\n",
         written, busy, states);
  destroy_spline_shm(shm);
  destroy_imu_shm(imu);
  return status;
}
