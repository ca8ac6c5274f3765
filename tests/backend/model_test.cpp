// The MJCF model against the published facts, and the project's kinematics against MuJoCo's.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <random>

#include "backend/sim_fixture.hpp"
#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

constexpr const char* kLegNames[] = {"FR", "FL", "RR", "RL"};
constexpr const char* kJointNames[] = {"abad", "hip", "knee"};

TEST(Model, LoadsWithOneMillisecondStepAndTheExpectedElements) {
  MujocoBackend backend(testing::sim_config());
  const mjModel* m = backend.model();
  EXPECT_DOUBLE_EQ(m->opt.timestep, 0.001);
  EXPECT_EQ(m->nu, 12);
  EXPECT_EQ(m->nq, 19);  // free joint + 12 hinges
}

TEST(Model, TotalMassIsWithinTheSpecification) {
  MujocoBackend backend(testing::sim_config());
  const mjModel* m = backend.model();
  double total = 0.0;
  for (int b = 0; b < m->nbody; ++b) total += m->body_mass[b];
  EXPECT_GE(total, 8.4);
  EXPECT_LE(total, 9.4);
  EXPECT_NEAR(total, 4.03 + 4 * (0.354 + 0.482 + 0.116) + 12 * 0.0567, 1e-9);
}

TEST(Model, JointLimitsEqualTheFacts) {
  MujocoBackend backend(testing::sim_config());
  const mjModel* m = backend.model();
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    for (std::size_t j = 0; j < kJointsPerLeg; ++j) {
      const std::string name = std::string(kLegNames[leg]) + "_" + kJointNames[j];
      const int id = mj_name2id(m, mjOBJ_JOINT, name.c_str());
      ASSERT_GE(id, 0) << name;
      EXPECT_TRUE(m->jnt_limited[id]) << name;
      const robot::JointRange range = robot::joint_range(joint_index(leg, j));
      EXPECT_DOUBLE_EQ(m->jnt_range[2 * id], range.lower) << name;
      EXPECT_DOUBLE_EQ(m->jnt_range[2 * id + 1], range.upper) << name;
      EXPECT_NEAR(m->dof_armature[m->jnt_dofadr[id]], 4.78e-5 * 7.75 * 7.75, 1e-5) << name;
    }
  }
}

TEST(Model, FootSitesMatchTheProjectKinematicsForRandomPoses) {
  // an independent check of leg_kinematics: MuJoCo's own forward kinematics of the model
  MujocoBackend backend(testing::sim_config(1.0));
  backend.set_base_pose({0.0, 0.0, 1.0}, {1.0, 0.0, 0.0, 0.0});
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> abad(-0.6, 0.6), hip(-0.9, 2.7), knee(-2.5, -0.6);
  for (int trial = 0; trial < 50; ++trial) {
    JointArray<double> q{};
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      q[3 * leg] = abad(rng);
      q[3 * leg + 1] = hip(rng);
      q[3 * leg + 2] = knee(rng);
    }
    backend.set_joint_positions(q);
    const mjData* d = backend.data();
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      const int site = mj_name2id(backend.model(), mjOBJ_SITE, (std::string(kLegNames[leg]) + "_foot").c_str());
      const Vec3 mujoco_foot(d->site_xpos[3 * site], d->site_xpos[3 * site + 1], d->site_xpos[3 * site + 2] - 1.0);
      const Vec3 ours = foot_position_in_body(leg, Vec3(q[3 * leg], q[3 * leg + 1], q[3 * leg + 2]));
      EXPECT_LT((mujoco_foot - ours).norm(), 1e-9) << kLegNames[leg];
    }
  }
}

TEST(Model, MissingFileIsReportedWithItsPath) {
  MujocoBackendConfig config = testing::sim_config();
  config.model_path = "/nonexistent/robot.xml";
  try {
    MujocoBackend backend(config);
    FAIL() << "no error for a missing model";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/robot.xml"), std::string::npos) << e.what();
  }
}

TEST(Model, BrokenFileIsReportedWithMujocosReason) {
  const std::string path = ::testing::TempDir() + "/broken_model.xml";
  {
    std::FILE* f = std::fopen(path.c_str(), "w");
    std::fputs("<mujoco><worldbody><body><geom type='sphere'/></worldbody></mujoco>", f);
    std::fclose(f);
  }
  MujocoBackendConfig config = testing::sim_config();
  config.model_path = path;
  try {
    MujocoBackend backend(config);
    FAIL() << "no error for a broken model";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find("failed to load"), std::string::npos) << message;
  }
}

TEST(Model, UnknownKeyframeNamesTheAcceptedOnes) {
  MujocoBackendConfig config = testing::sim_config();
  config.initial_keyframe = "sitting";
  EXPECT_THROW({ MujocoBackend backend(config); }, std::runtime_error);
}

}  // namespace
}  // namespace cerebellum
