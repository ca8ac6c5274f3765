// Lockstep runs are reproducible to the bit, and the noise seed really matters.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <cstring>
#include <vector>

#include "backend/sim_fixture.hpp"
#include "control/stand_up_controller.hpp"

namespace cerebellum {
namespace {

// full physics state after every tick of a 2 s stand-up with noisy sensors
std::vector<double> trajectory(unsigned seed) {
  StandUpController stand_up(default_stand_up_config());
  testing::LockstepSim sim(testing::sim_config(0.3, /*noise=*/true, seed), stand_up);
  std::vector<double> states;
  const mjModel* m = sim.backend.model();
  while (sim.backend.time_s() < 2.0 - 1e-9) {
    sim.loop.tick();
    const mjData* d = sim.backend.data();
    states.insert(states.end(), d->qpos, d->qpos + m->nq);
    states.insert(states.end(), d->qvel, d->qvel + m->nv);
  }
  return states;
}

TEST(Determinism, SameSeedGivesBitwiseIdenticalTrajectories) {
  const std::vector<double> a = trajectory(42);
  const std::vector<double> b = trajectory(42);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
}

TEST(Determinism, DifferentSeedsGiveDifferentTrajectories) {
  const std::vector<double> a = trajectory(1);
  const std::vector<double> b = trajectory(2);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_NE(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
}

}  // namespace
}  // namespace cerebellum
