// One flip (16/20 back, 16/21 front) through the whole MC in lockstep, judged on the simulator's
// truth: what the flip benchmark tabulates over its seeds and the Release stage's seeded tests
// assert, one home for both (bench/flip_bench.cpp, tests/sweep/flip_trial_test.cpp).
#pragma once

#include "loop/mc_config.hpp"

namespace cerebellum {

struct FlipTrial {
  double turned_rad = 0.0;          // the trunk's pitch rate integrated from the command on
  double distance_m = 0.0;          // where it stands from where it took off, on the ground
  double peak_torque_nm = 0.0;      // the largest torque a motor applied
  double temperature_rise_c = 0.0;  // the hottest winding's rise over the flip
  // damped, or once the landing has begun tilted past 1 rad or with the trunk below 0.1 m
  bool fell = false;
  // the response at 100 in 16, the trunk above 0.2 m and level within 0.1 rad
  bool stood = false;
};

// from config's robot lying at start: the recovery stand (3 s), the locomotion stand (1 s), then
// the flip of flip_gait_id (kBackFlipGaitId or kFrontFlipGaitId, modes/jump_mode.hpp) for 5 s
FlipTrial run_flip_trial(const McConfig& config, int flip_gait_id);

}  // namespace cerebellum
