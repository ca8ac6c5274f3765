// The planar flip model against MuJoCo's inverse dynamics of the robot's own model file, the left
// and right legs moving alike: the same masses, lengths, inertias and armature, one home each.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <array>
#include <cmath>
#include <string>

#include "control/flip_plan/planar_model.hpp"

namespace cerebellum::flip {
namespace {

struct MujocoModel {
  mjModel* model = nullptr;
  mjData* data = nullptr;
  MujocoModel() {
    char error[512] = "";
    model = mj_loadXML((std::string(CEREBELLUM_MODEL_DIR) + "/cyberdog2.xml").c_str(), nullptr, error, sizeof error);
    if (model == nullptr) return;
    // rigid bodies only: no joint damping, no dry friction, no contacts
    for (int i = 0; i < model->nv; ++i) model->dof_damping[i] = 0.0;
    model->opt.disableflags |= mjDSBL_CONSTRAINT;
    data = mj_makeData(model);
  }
  ~MujocoModel() {
    if (data != nullptr) mj_deleteData(data);
    if (model != nullptr) mj_deleteModel(model);
  }
};

// MuJoCo's joint order: FR, FL, RR, RL, each abad, hip, knee after the free joint
constexpr int kFreeQpos = 7;
constexpr int kFreeDof = 6;
int mujoco_leg(int pair, int side) { return pair == kFrontPair ? side : 2 + side; }

// the generalised forces MuJoCo needs for (q, qd, qdd) of the planar model, in planar coordinates
std::array<double, kDof> mujoco_forces(MujocoModel& mj, const double* q, const double* qd, const double* qdd) {
  mjData* d = mj.data;
  mju_zero(d->qpos, mj.model->nq);
  mju_zero(d->qvel, mj.model->nv);
  mju_zero(d->qacc, mj.model->nv);
  d->qpos[0] = q[kX];
  d->qpos[2] = q[kZ];
  d->qpos[3] = std::cos(0.5 * q[kPitch]);
  d->qpos[5] = std::sin(0.5 * q[kPitch]);
  d->qvel[0] = qd[kX], d->qvel[2] = qd[kZ], d->qvel[4] = qd[kPitch];
  d->qacc[0] = qdd[kX], d->qacc[2] = qdd[kZ], d->qacc[4] = qdd[kPitch];
  for (int pair = 0; pair < kPairs; ++pair)
    for (int side = 0; side < 2; ++side)
      for (int joint = 0; joint < 2; ++joint) {
        const int leg = mujoco_leg(pair, side);
        const int c = hip_coordinate(pair) + joint;
        d->qpos[kFreeQpos + 3 * leg + 1 + joint] = q[c];
        d->qvel[kFreeDof + 3 * leg + 1 + joint] = qd[c];
        d->qacc[kFreeDof + 3 * leg + 1 + joint] = qdd[c];
      }
  mj_inverse(mj.model, d);
  std::array<double, kDof> forces{};
  forces[kX] = d->qfrc_inverse[0];
  forces[kZ] = d->qfrc_inverse[2];
  forces[kPitch] = d->qfrc_inverse[4];
  for (int pair = 0; pair < kPairs; ++pair)
    for (int joint = 0; joint < 2; ++joint)
      forces[hip_coordinate(pair) + joint] = d->qfrc_inverse[kFreeDof + 3 * mujoco_leg(pair, 0) + 1 + joint] +
                                             d->qfrc_inverse[kFreeDof + 3 * mujoco_leg(pair, 1) + 1 + joint];
  return forces;
}

TEST(PlanarModel, ItsMassIsTheRobotsMass) {
  EXPECT_NEAR(planar_total_mass_kg(planar_bodies()), robot::kTotalMassKg, 0.005);
}

TEST(PlanarModel, TheForcesAMotionNeedsAreMujocosForTheSameMotionOfBothSides) {
  MujocoModel mj;
  ASSERT_NE(mj.model, nullptr);
  const std::vector<PlanarBody> bodies = planar_bodies();
  // a stand at rest, then motions with every coordinate moving, turned up to past a half flip
  const double states[][3][kDof] = {
      {{0.0, 0.26, 0.0, 0.79, -1.22, 0.79, -1.22}, {0, 0, 0, 0, 0, 0, 0}, {0, 0, 0, 0, 0, 0, 0}},
      {{0.1, 0.3, -0.7, 0.3, -0.9, 1.9, -2.2}, {0.5, 1.2, -6.0, 8.0, -4.0, 12.0, 3.0}, {2.0, -3.0, -40.0, 90.0, 30.0, -50.0, 70.0}},
      {{-0.3, 0.45, -3.5, 1.5, -1.6, 2.8, -0.7}, {-1.0, 0.3, -11.0, -15.0, 20.0, -7.0, 25.0}, {0.0, -9.81, 5.0, -200.0, 100.0, 60.0, -80.0}},
  };
  const double no_torque[4] = {0, 0, 0, 0};
  const double no_force[4] = {0, 0, 0, 0};
  for (const auto& state : states) {
    double residual[kDof];
    dynamics_residual(bodies, state[0], state[1], state[2], no_torque, no_force, residual);
    const std::array<double, kDof> expected = mujoco_forces(mj, state[0], state[1], state[2]);
    for (int j = 0; j < kDof; ++j) EXPECT_NEAR(residual[j], expected[j], 1e-6 + 1e-6 * std::abs(expected[j])) << "coordinate " << j;
  }
}

TEST(PlanarModel, AFootsPlaceIsTheLegKinematicsOfTheSdk) {
  // the stand pose: the foot centre below the hip by the sagittal leg, forward by its offset
  const double q[kDof] = {0.0, 0.3, 0.0, robot::kStandPose[1], robot::kStandPose[2], robot::kStandPose[1], robot::kStandPose[2]};
  const Point2<double> front = foot_position(q, kFrontPair);
  const double hip = robot::kStandPose[1];
  const double knee = robot::kStandPose[2];
  EXPECT_NEAR(front.x, robot::kHipX - robot::kThighLength * std::sin(hip) - robot::kShankLength * std::sin(hip + knee), 1e-12);
  EXPECT_NEAR(front.z, 0.3 - robot::kThighLength * std::cos(hip) - robot::kShankLength * std::cos(hip + knee), 1e-12);
}

}  // namespace
}  // namespace cerebellum::flip
