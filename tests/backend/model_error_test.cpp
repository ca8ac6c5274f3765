// The simulated robot's model error (backend/model_error.hpp), each part checked on MuJoCo's own
// quantities or on the physics it changes: the payload and the moved centre of mass in the
// compiled model and in the subtree's centre of mass, the feet's friction by a sliding block
// test, the motor strength on the torque that reaches the joint, the actuation delay on when a
// new command's torque appears.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <cmath>

#include "backend/sim_fixture.hpp"

namespace cerebellum {
namespace {

double total_mass_kg(const mjModel* m) {
  double total = 0.0;
  for (int b = 0; b < m->nbody; ++b) total += m->body_mass[b];
  return total;
}

TEST(ModelError, APayloadAddsItsMassToTheTrunkAndTheRobotsWeight) {
  MujocoBackend exact(testing::sim_config());
  MujocoBackendConfig config = testing::sim_config();
  config.model_error.added_mass_kg = 1.2;
  MujocoBackend loaded(config);
  EXPECT_NEAR(total_mass_kg(loaded.model()) - total_mass_kg(exact.model()), 1.2, 1e-12);
  // MuJoCo's derived subtree mass of the world (recomputed by mj_setConst) agrees
  EXPECT_NEAR(loaded.model()->body_subtreemass[0], total_mass_kg(loaded.model()), 1e-9);
  const int trunk = mj_name2id(loaded.model(), mjOBJ_BODY, "trunk");
  const double scale = loaded.model()->body_mass[trunk] / exact.model()->body_mass[trunk];
  EXPECT_NEAR(loaded.model()->body_inertia[3 * trunk + 1], scale * exact.model()->body_inertia[3 * trunk + 1], 1e-12);
}

TEST(ModelError, AMovedCentreOfMassMovesTheTrunksCentreOfMassInTheWorld) {
  MujocoBackend exact(testing::sim_config());
  MujocoBackendConfig config = testing::sim_config();
  config.model_error.com_offset_m = {0.02, -0.015, 0.01};
  MujocoBackend moved(config);
  const int trunk = mj_name2id(moved.model(), mjOBJ_BODY, "trunk");
  // same start pose: the trunk's frame is where it was, its centre of mass is not
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(moved.data()->xpos[3 * trunk + k], exact.data()->xpos[3 * trunk + k], 1e-12);
  }
  // the trunk's orientation maps the offset into the world (xmat row-major)
  const double* r = exact.data()->xmat + 9 * trunk;
  const double offset[3] = {0.02, -0.015, 0.01};
  for (int k = 0; k < 3; ++k) {
    const double expected = exact.data()->xipos[3 * trunk + k] + r[3 * k] * offset[0] + r[3 * k + 1] * offset[1] +
                            r[3 * k + 2] * offset[2];
    EXPECT_NEAR(moved.data()->xipos[3 * trunk + k], expected, 1e-12);
  }
}

// a foot geom's contacts with the floor: the friction MuJoCo chose for them (the robot put down
// on its feet, motors passive)
double foot_contact_friction(MujocoBackend& backend) {
  for (int i = 0; i < 100; ++i) backend.advance(0.001);
  const mjModel* m = backend.model();
  const mjData* d = backend.data();
  const int foot = mj_name2id(m, mjOBJ_GEOM, "FR_foot");
  for (int c = 0; c < d->ncon; ++c) {
    if (d->contact[c].geom1 == foot || d->contact[c].geom2 == foot) return d->contact[c].friction[0];
  }
  return -1.0;
}

TEST(ModelError, TheFeetsFrictionIsTheOneTheContactsUseEvenBelowTheFloors) {
  MujocoBackendConfig slippery = testing::sim_config();
  slippery.initial_keyframe = "stand";
  slippery.model_error.foot_friction = 0.4;
  MujocoBackend low(slippery);
  EXPECT_NEAR(foot_contact_friction(low), 0.4, 1e-12);
  MujocoBackendConfig grippy = testing::sim_config();
  grippy.initial_keyframe = "stand";
  grippy.model_error.foot_friction = 1.2;
  MujocoBackend high(grippy);
  EXPECT_NEAR(foot_contact_friction(high), 1.2, 1e-12);
}

// one joint's torque after a pure feed-forward command, the robot hung in the air
double applied_knee_torque_nm(MujocoBackend& backend) {
  return backend.data()->actuator_force[mj_name2id(backend.model(), mjOBJ_ACTUATOR, "FR_knee")];
}

JointCommand knee_torque_command(double tau_nm) {
  JointCommand command{};
  command.tau_ff[2] = tau_nm;
  return command;
}

TEST(ModelError, AWeakerMotorGivesLessTorqueForTheSameCommandAndReportsTheDataSheetsFigure) {
  MujocoBackendConfig config = testing::sim_config(1.0);
  config.model_error.motor_strength_scale = 0.85;
  MujocoBackend weak(config);
  weak.write(knee_torque_command(4.0));
  weak.advance(0.001);
  EXPECT_NEAR(applied_knee_torque_nm(weak), 0.85 * 4.0, 1e-9);
  EXPECT_NEAR(weak.read().tau[2], 4.0, 1e-9);
  // and its limit with it: asking for far more gives the scaled maximum
  weak.write(knee_torque_command(100.0));
  weak.advance(0.001);
  EXPECT_NEAR(applied_knee_torque_nm(weak), 0.85 * MotorLimits{}.torque_max_nm, 1e-6);
}

TEST(ModelError, ALateActuationAppliesEachCommandItsDelayAfterItWasWritten) {
  MujocoBackendConfig config = testing::sim_config(1.0);
  config.model_error.actuation_delay_s = 0.003;
  MujocoBackend late(config);
  late.write(knee_torque_command(2.0));
  const double written_s = late.time_s();
  double first_seen_s = -1.0;
  for (int step = 0; step < 10 && first_seen_s < 0.0; ++step) {
    const double step_start_s = late.time_s();
    late.advance(0.001);
    if (std::abs(applied_knee_torque_nm(late) - 2.0) < 1e-9) first_seen_s = step_start_s;
  }
  EXPECT_NEAR(first_seen_s - written_s, 0.003, 1e-9);
  // without the delay, the next physics step applies it
  MujocoBackend exact(testing::sim_config(1.0));
  exact.write(knee_torque_command(2.0));
  exact.advance(0.001);
  EXPECT_NEAR(applied_knee_torque_nm(exact), 2.0, 1e-9);
}

TEST(ModelError, ADelayBeyondTenMillisecondsOrAVanishingTrunkIsRefused) {
  MujocoBackendConfig late = testing::sim_config();
  late.model_error.actuation_delay_s = 0.02;
  EXPECT_THROW(MujocoBackend{late}, std::runtime_error);
  MujocoBackendConfig light = testing::sim_config();
  light.model_error.added_mass_kg = -100.0;
  EXPECT_THROW(MujocoBackend{light}, std::runtime_error);
}

}  // namespace
}  // namespace cerebellum
