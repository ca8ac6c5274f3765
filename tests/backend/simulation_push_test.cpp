// The push as a disturbance input of the simulation: posted through the simulation handle (from
// any thread), turned into a force on the trunk by the simulation at its own physics steps.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <array>
#include <cmath>
#include <thread>

#include "backend/sim_fixture.hpp"
#include "backend/simulation.hpp"

namespace cerebellum {
namespace {

std::array<double, 3> trunk_force(const Simulation& simulation) {
  const mjModel* model = simulation.model();
  const int trunk = mj_name2id(model, mjOBJ_BODY, "trunk");
  const double* f = simulation.data()->xfrc_applied + 6 * trunk;
  return {f[0], f[1], f[2]};
}

TEST(SimulationPush, PullsTheTrunkWithTheSpringOnTheStateOfTheStep) {
  MujocoBackend backend(testing::sim_config(1.0));
  Simulation& simulation = backend;
  backend.advance(0.02);  // falling: the damping term is not zero
  backend.read();         // brings the derived quantities (COM) to the current state
  const mjData* data = simulation.data();
  const int trunk = mj_name2id(simulation.model(), mjOBJ_BODY, "trunk");
  const std::array<double, 3> com{data->xipos[3 * trunk], data->xipos[3 * trunk + 1], data->xipos[3 * trunk + 2]};
  const std::array<double, 3> velocity{data->qvel[0], data->qvel[1], data->qvel[2]};
  ASSERT_LT(velocity[2], -0.1);

  PushRequest request;
  request.active = true;
  request.target_world = {com[0] + 0.02, com[1] - 0.03, com[2] + 0.01};
  simulation.request_push(request);
  backend.advance(simulation.physics_timestep_s());  // one physics step

  // by hand, with the default spring (150 N/m, 15 N s/m, 40 N at most; well below here)
  const PushSpring spring;
  std::array<double, 3> expected{};
  for (int k = 0; k < 3; ++k) {
    expected[k] =
        spring.stiffness_n_per_m * (request.target_world[k] - com[k]) - spring.damping_n_s_per_m * velocity[k];
  }
  ASSERT_LT(std::hypot(expected[0], expected[1], expected[2]), spring.max_force_n);
  const std::array<double, 3> force = trunk_force(simulation);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(force[k], expected[k], 1e-9) << k;
}

TEST(SimulationPush, ReleasedPushLiftsItsForceAndLeavesOtherForcesAlone) {
  MujocoBackend backend(testing::sim_config(1.0));
  Simulation& simulation = backend;
  const double step_s = simulation.physics_timestep_s();

  simulation.set_external_force({0.0, 0.0, 5.0});
  backend.advance(step_s);
  EXPECT_EQ(trunk_force(simulation), (std::array<double, 3>{0.0, 0.0, 5.0}));  // no push: untouched

  simulation.request_push({true, {1.0, 0.0, 1.0}});
  backend.advance(step_s);
  EXPECT_GT(trunk_force(simulation)[0], 1.0);

  simulation.request_push({});
  backend.advance(step_s);
  EXPECT_EQ(trunk_force(simulation), (std::array<double, 3>{0.0, 0.0, 0.0}));

  simulation.set_external_force({1.0, 2.0, 3.0});
  backend.advance(step_s);
  EXPECT_EQ(trunk_force(simulation), (std::array<double, 3>{1.0, 2.0, 3.0}));
}

TEST(SimulationPush, RequestPostedFromAnotherThreadActsAtTheNextStep) {
  MujocoBackend backend(testing::sim_config(1.0));
  Simulation& simulation = backend;
  std::thread viewer([&] { simulation.request_push({true, {0.0, 1.0, 1.0}}); });
  viewer.join();
  EXPECT_EQ(trunk_force(simulation), (std::array<double, 3>{0.0, 0.0, 0.0}));
  backend.advance(simulation.physics_timestep_s());
  EXPECT_GT(trunk_force(simulation)[1], 1.0);
}

TEST(SimulationForcePulse, PushesWithItsForceForItsSimulatedDurationOnTopOfThePush) {
  MujocoBackend backend(testing::sim_config(1.0));
  Simulation& simulation = backend;
  const double step_s = simulation.physics_timestep_s();
  std::thread tool([&] { simulation.request_force_pulse({{30.0, -20.0, 5.0}, 10 * step_s}); });
  tool.join();
  for (int step = 0; step < 10; ++step) {
    backend.advance(step_s);
    EXPECT_EQ(trunk_force(simulation), (std::array<double, 3>{30.0, -20.0, 5.0})) << step;
  }
  backend.advance(step_s);  // over: the force is lifted
  EXPECT_EQ(trunk_force(simulation), (std::array<double, 3>{0.0, 0.0, 0.0}));

  // with the viewer's push at the same time: the sum
  simulation.request_push({true, {1.0, 0.0, 1.0}});
  backend.advance(step_s);
  const std::array<double, 3> push_only = trunk_force(simulation);
  simulation.request_force_pulse({{0.0, 0.0, 40.0}, 1.0});
  backend.advance(step_s);
  EXPECT_NEAR(trunk_force(simulation)[2] - push_only[2], 40.0, 1.0);  // the spring moved a little
}

TEST(SimulationForcePulse, MovesTheRobotsCentreOfMassAsNewtonSays) {
  // in free fall from 1 m (no contact for 0.4 s) only gravity and the pulse act sideways:
  // y = F t^2 / (2 M) during the pulse, then on at v = F T / M
  MujocoBackend backend(testing::sim_config(1.0));
  Simulation& simulation = backend;
  double total_mass_kg = 0.0;
  for (int body = 0; body < simulation.model()->nbody; ++body) total_mass_kg += simulation.model()->body_mass[body];
  const int trunk = mj_name2id(simulation.model(), mjOBJ_BODY, "trunk");
  const auto com_y = [&] {
    backend.read();  // brings the derived quantities (subtree COM) to the current state
    return simulation.data()->subtree_com[3 * trunk + 1];
  };
  const double y0 = com_y();
  const double force_n = 50.0;
  const double pulse_s = 0.1;
  simulation.request_force_pulse({{0.0, force_n, 0.0}, pulse_s});
  backend.advance(pulse_s);
  const double expected_after_pulse_m = force_n * pulse_s * pulse_s / (2.0 * total_mass_kg);
  EXPECT_NEAR(com_y() - y0, expected_after_pulse_m, 0.03 * expected_after_pulse_m);
  backend.advance(0.1);
  const double expected_later_m = expected_after_pulse_m + force_n * pulse_s / total_mass_kg * 0.1;
  EXPECT_NEAR(com_y() - y0, expected_later_m, 0.03 * expected_later_m);
}

}  // namespace
}  // namespace cerebellum
