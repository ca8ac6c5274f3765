// Leg gravity torques against MuJoCo's generalised gravity force of the same model.
#include "control/leg_gravity.hpp"

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <random>
#include <string>

#include <Eigen/Geometry>

#include "backend/sim_fixture.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

TEST(LegGravity, MatchesTheSimulatorsGravityForceInRandomPoses) {
  MujocoBackend backend(testing::sim_config());
  mjData* data = mj_makeData(backend.model());
  const mjModel* model = backend.model();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  static const char* const kJoints[kNumJoints] = {"FR_abad", "FR_hip", "FR_knee", "FL_abad", "FL_hip", "FL_knee",
                                                  "RR_abad", "RR_hip", "RR_knee", "RL_abad", "RL_hip", "RL_knee"};
  for (int trial = 0; trial < 20; ++trial) {
    // random trunk orientation and joint angles inside their ranges, at rest
    const Eigen::Quaterniond orientation = Eigen::Quaterniond::UnitRandom().normalized();
    mju_zero(data->qvel, model->nv);
    data->qpos[3] = orientation.w();
    data->qpos[4] = orientation.x();
    data->qpos[5] = orientation.y();
    data->qpos[6] = orientation.z();
    JointArray<double> q{};
    for (std::size_t i = 0; i < kNumJoints; ++i) {
      const robot::JointRange range = robot::joint_range(i);
      q[i] = range.lower + (range.upper - range.lower) * unit(rng);
      data->qpos[model->jnt_qposadr[mj_name2id(model, mjOBJ_JOINT, kJoints[i])]] = q[i];
    }
    mj_forward(model, data);
    const Eigen::Vector3d gravity_body = orientation.conjugate() * Eigen::Vector3d(0.0, 0.0, -9.81);
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      const Eigen::Vector3d tau =
          leg_gravity_torque(leg, Eigen::Vector3d(q[3 * leg], q[3 * leg + 1], q[3 * leg + 2]), gravity_body);
      for (std::size_t k = 0; k < kJointsPerLeg; ++k) {
        const int dof = model->jnt_dofadr[mj_name2id(model, mjOBJ_JOINT, kJoints[3 * leg + k])];
        // at rest the bias force is the torque that holds the joint against gravity
        EXPECT_NEAR(tau[static_cast<Eigen::Index>(k)], data->qfrc_bias[dof], 1e-6) << "leg " << leg << " joint " << k;
      }
    }
  }
  mj_deleteData(data);
}

TEST(LegGravity, TheWholeBodyCentreOfMassIsTheSimulatorsInStandAndRandomLegPoses) {
  MujocoBackend backend(testing::sim_config());
  const mjModel* model = backend.model();
  mjData* data = mj_makeData(model);
  static const char* const kJoints[kJointsPerLeg] = {"abad", "hip", "knee"};
  static const char* const kLegs[kNumLegs] = {"FR", "FL", "RR", "RL"};
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 6; ++trial) {
    std::array<double, 3> q = robot::kStandPose;
    if (trial > 0) {
      for (std::size_t k = 0; k < kJointsPerLeg; ++k) {
        const robot::JointRange range = robot::joint_range(k);
        q[k] = range.lower + (range.upper - range.lower) * unit(rng);
      }
    }
    // the trunk at the origin, level
    mju_zero(data->qpos, model->nq);
    data->qpos[3] = 1.0;
    for (const char* leg : kLegs) {
      for (std::size_t k = 0; k < kJointsPerLeg; ++k) {
        const std::string name = std::string(leg) + "_" + kJoints[k];
        data->qpos[model->jnt_qposadr[mj_name2id(model, mjOBJ_JOINT, name.c_str())]] = q[k];
      }
    }
    mj_forward(model, data);
    const int trunk = mj_name2id(model, mjOBJ_BODY, "trunk");
    const Eigen::Vector3d simulator(data->subtree_com[3 * trunk], data->subtree_com[3 * trunk + 1],
                                    data->subtree_com[3 * trunk + 2]);
    EXPECT_LT((whole_body_com_in_body(q) - simulator).norm(), 2e-5)
        << "trial " << trial << ": " << whole_body_com_in_body(q).transpose() << " vs " << simulator.transpose();
  }
  EXPECT_EQ(stand_com_in_body(), whole_body_com_in_body(robot::kStandPose));
  mj_deleteData(data);
}

TEST(LegGravity, VanishesWithoutGravity) {
  EXPECT_TRUE(leg_gravity_torque(0, Eigen::Vector3d(0.1, 0.8, -1.2), Eigen::Vector3d::Zero()).isZero());
}

}  // namespace
}  // namespace cerebellum
