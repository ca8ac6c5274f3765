// The simulation's ground truth: foot contacts agree with the feet's heights above the floor, and
// the joints are the simulator's own state.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <cmath>

#include "backend/sim_fixture.hpp"
#include "control/stand_up_controller.hpp"

namespace cerebellum {
namespace {

constexpr std::array<const char*, kNumLegs> kFootSites{"FR_foot", "FL_foot", "RR_foot", "RL_foot"};

// height of the foot sphere's centre above the floor plane z = 0
double foot_centre_height_m(const Simulation& simulation, std::size_t leg) {
  const int site = mj_name2id(simulation.model(), mjOBJ_SITE, kFootSites[leg]);
  return simulation.data()->site_xpos[3 * site + 2];
}

double foot_radius_m(const Simulation& simulation, std::size_t leg) {
  const int geom = mj_name2id(simulation.model(), mjOBJ_GEOM, kFootSites[leg]);
  return simulation.model()->geom_size[3 * geom];
}

TEST(GroundTruth, FootContactsAgreeWithTheFeetHeightsWhileALimpRobotFallsAndSettles) {
  class Limp final : public MotionController {
    void compute(const RobotState&, JointCommand& command) override { command = JointCommand{}; }
  } limp;
  testing::LockstepSim sim(testing::sim_config(0.45), limp);
  int ticks_with_all_feet_down = 0;
  while (sim.backend.time_s() < 2.0) {
    sim.loop.tick();
    const GroundTruth truth = sim.backend.ground_truth();
    int down = 0;
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      const double gap_m = foot_centre_height_m(sim.backend, leg) - foot_radius_m(sim.backend, leg);
      if (truth.foot_contact[leg]) {
        EXPECT_LT(gap_m, 0.002) << "leg " << leg << " at t " << sim.backend.time_s();
      }
      if (gap_m < -0.001) {
        EXPECT_TRUE(truth.foot_contact[leg]) << "leg " << leg << " at t " << sim.backend.time_s();
      }
      down += truth.foot_contact[leg] ? 1 : 0;
    }
    if (down == static_cast<int>(kNumLegs)) ++ticks_with_all_feet_down;
  }
  // the check above saw both kinds of moments, not only "all in the air"
  EXPECT_GT(ticks_with_all_feet_down, 0);
}

TEST(GroundTruth, TheFeetCarryTheRobotsWeightWhenItStandsStill) {
  StandUpController stand_up(default_stand_up_config());
  testing::LockstepSim sim(testing::sim_config(0.3), stand_up);
  sim.run_for(3.0);
  // standing still: the ground holds the whole robot's weight (MuJoCo's masses, summed here)
  double mass_kg = 0.0;
  for (int body = 0; body < sim.backend.model()->nbody; ++body) mass_kg += sim.backend.model()->body_mass[body];
  const GroundTruth truth = sim.backend.ground_truth();
  double total_n = 0.0;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    EXPECT_GT(truth.foot_force_z_n[leg], 0.1 * mass_kg * 9.81) << "leg " << leg;
    total_n += truth.foot_force_z_n[leg];
  }
  EXPECT_NEAR(total_n, mass_kg * sim.backend.model()->opt.gravity[2] * -1.0, 0.02 * mass_kg * 9.81);
  // in the air, none
  sim.backend.set_base_pose({0.0, 0.0, 1.0}, {1.0, 0.0, 0.0, 0.0});
  for (double force : sim.backend.ground_truth().foot_force_z_n) EXPECT_EQ(force, 0.0);
}

TEST(GroundTruth, ALiftedRobotHasNoFootOnTheGround) {
  StandUpController stand_up(default_stand_up_config());
  testing::LockstepSim sim(testing::sim_config(0.3), stand_up);
  sim.run_for(2.0);
  for (bool contact : sim.backend.ground_truth().foot_contact) EXPECT_TRUE(contact);
  sim.backend.set_base_pose({0.0, 0.0, 1.0}, {1.0, 0.0, 0.0, 0.0});
  for (bool contact : sim.backend.ground_truth().foot_contact) EXPECT_FALSE(contact);
}

TEST(GroundTruth, JointsAreTheSimulatorStateAndTheAppliedTorque) {
  StandUpController stand_up(default_stand_up_config());
  testing::LockstepSim sim(testing::sim_config(0.3), stand_up);
  sim.run_for(0.5);
  const SensorFrame frame = sim.backend.read();  // noise off: the sensors are the state
  const GroundTruth truth = sim.backend.ground_truth();
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    EXPECT_DOUBLE_EQ(truth.q[i], frame.q[i]);
    EXPECT_DOUBLE_EQ(truth.qd[i], frame.qd[i]);
    EXPECT_DOUBLE_EQ(truth.tau[i], frame.tau[i]);
  }
  double torque_sum_nm = 0.0;
  for (double tau : truth.tau) torque_sum_nm += std::abs(tau);
  EXPECT_GT(torque_sum_nm, 1.0);  // rising: the motors work
}

}  // namespace
}  // namespace cerebellum
