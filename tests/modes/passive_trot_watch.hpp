// What the passive trot's simulation tests watch (tests/modes/passive_trot_*): the trot entered,
// the feet's lifts and the trunk on the simulator's truth while pulled, and the stand after a
// release. Shared by the short cases (test_modes_sim) and the seeded ones (test_passive_trot_seeds).
#pragma once

#include <algorithm>
#include <cmath>
#include <ostream>

#include <gtest/gtest.h>

#include "control/locomotion/gait_table.hpp"
#include "modes/mode_sim.hpp"

namespace cerebellum {
namespace testing {

inline HighLevelCommand passive_trot(float vx = 0.0f) {
  HighLevelCommand c = command(ModeId::Locomotion, kPassiveTrotGaitId);
  c.vel_des = {vx, 0.0f, 0.0f};
  return c;
}

inline bool all_feet_down(const ModeSim& sim) {
  const GroundTruth truth = sim.backend.ground_truth();
  return std::all_of(truth.foot_contact.begin(), truth.foot_contact.end(), [](bool c) { return c; });
}

inline Eigen::Vector2d true_xy(const ModeSim& sim) {
  const GroundTruth truth = sim.backend.ground_truth();
  return {truth.position[0], truth.position[1]};
}

inline bool upright(const ModeSim& sim) {
  return sim.true_height() > 0.18 && std::abs(sim.true_rpy().x()) < 0.5 && std::abs(sim.true_rpy().y()) < 0.5;
}

// stands up, then enters gait 4 and waits for it to settle
inline void stand_in_passive_trot(ModeSim& sim) {
  sim.run(3.0);
  sim.send(passive_trot(), 1.5);
  ASSERT_EQ(sim.status().mode, 11);
  ASSERT_EQ(sim.status().gait_id, kPassiveTrotGaitId);
}

// the longest time within `seconds` during which some foot was in the air, and the trunk's travel
struct Watch {
  double longest_lift_s = 0.0;
  bool stayed_up = true;
  double worst_tilt_rad = 0.0;
  double lowest_m = 1.0;
};
inline Watch watch(ModeSim& sim, double seconds) {
  Watch w;
  double lifted_s = 0.0;
  const double end = sim.time_s() + seconds - 1e-9;
  while (sim.time_s() < end) {
    sim.run(0.002);
    lifted_s = all_feet_down(sim) ? 0.0 : lifted_s + 0.002;
    w.longest_lift_s = std::max(w.longest_lift_s, lifted_s);
    w.stayed_up = w.stayed_up && upright(sim);
    w.worst_tilt_rad = std::max({w.worst_tilt_rad, std::abs(sim.true_rpy().x()), std::abs(sim.true_rpy().y())});
    w.lowest_m = std::min(w.lowest_m, sim.true_height());
  }
  return w;
}

// after a release, for `seconds`: whether it stayed upright throughout, and how long until it stood
// (every foot down, trunk below 0.15 m/s) from then on to the end; -1 when it never did
struct Release {
  bool stayed_up = true;
  double standing_after_s = -1.0;
};
inline Release watch_release(ModeSim& sim, double seconds) {
  Release r;
  const double release_s = sim.time_s();
  double stood_since_s = -1.0;
  while (sim.time_s() < release_s + seconds - 1e-9) {
    sim.run(0.002);
    const GroundTruth t = sim.backend.ground_truth();
    const bool standing = all_feet_down(sim) && std::hypot(t.velocity_world[0], t.velocity_world[1]) < 0.15;
    if (!standing) stood_since_s = -1.0;
    if (standing && stood_since_s < 0.0) stood_since_s = sim.time_s();
    r.stayed_up = r.stayed_up && upright(sim);
  }
  r.standing_after_s = stood_since_s < 0.0 ? -1.0 : stood_since_s - release_s;
  return r;
}

// the cases, instantiated by each program with its own values
class PassiveTrotAlone : public ::testing::TestWithParam<unsigned> {};  // 0: no sensor noise; else its seed

struct PullCase {
  double fx_n, fy_n;
  unsigned noise_seed;  // 0: no sensor noise
};
class PassiveTrotPull : public ::testing::TestWithParam<PullCase> {};
// the case in the test's name (gtest's default prints the struct's bytes, padding included)
inline void PrintTo(const PullCase& c, std::ostream* out) {
  *out << c.fx_n << " N x, " << c.fy_n << " N y, noise seed " << c.noise_seed;
}

// As a client does it (12, then 11/4 as soon as the stand reports bar >= 95): a pull of 1-4 s
// started 0.5-5 s after entering gait 4; released, it stands within 1.5 s every time. With the
// 5 cm steps `cerebellum cmd walk --gait 4` asks for, the trot in place used to keep itself going
// (issue 47: its force estimate stayed above the old 5 N stop threshold)
struct LatePullCase {
  double wait_s;  // after entering gait 4
  double pull_s;
  float step_height_m;  // 0: the gait's own
  unsigned noise_seed;  // 0: no sensor noise
};
class PassiveTrotLatePull : public ::testing::TestWithParam<LatePullCase> {};
inline void PrintTo(const LatePullCase& c, std::ostream* out) {
  *out << "after " << c.wait_s << " s, pulled " << c.pull_s << " s, steps " << c.step_height_m << " m, noise seed "
       << c.noise_seed;
}

}  // namespace testing
}  // namespace cerebellum
