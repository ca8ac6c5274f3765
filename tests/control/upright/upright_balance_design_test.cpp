// The two-leg stand's design, checked in MuJoCo itself: every pose of the family is balanced on
// the hind feet alone (centre of mass over their contact points, only they touch, within the
// 12 Nm joints), and each gain, acting on the simulator's true state, holds its pose against a
// push, which the pose's torques alone do not.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "control/upright/upright_balance_design.hpp"
#include "control/upright/upright_state.hpp"
#include "core/robot_model.hpp"
#include "mujoco_model.hpp"

namespace cerebellum {
namespace {

using Sim = testing::MujocoModel;
using testing::robot_model_path;

const std::vector<UprightSample>& family() {
  static const std::vector<UprightSample> samples =
      design_upright_balance(robot_model_path(), UprightDesignConfig{}, 0.002);
  return samples;
}

TEST(UprightBalanceDesign, EveryPoseStandsOnTheHindFeetAloneWithTheCentreOfMassOverThem) {
  const std::vector<UprightSample>& samples = family();
  ASSERT_EQ(samples.size(), 12u);
  EXPECT_NEAR(samples.front().elevation_rad, UprightDesignConfig{}.start_elevation_rad, 1e-12);
  EXPECT_NEAR(samples.back().elevation_rad, UprightDesignConfig{}.end_elevation_rad, 1e-12);
  Sim sim;
  for (const UprightSample& sample : samples) {
    std::copy(sample.position.data(), sample.position.data() + sample.position.size(), sim.d->qpos);
    mju_zero(sim.d->qvel, sim.m->nv);
    mj_forward(sim.m, sim.d);
    // the contacts: the two hind feet, under the whole body's centre of mass (the contact point
    // is under the foot's centre)
    ASSERT_EQ(sim.d->ncon, 2) << "elevation " << sample.elevation_rad;
    double contact_x = 0.0;
    for (int c = 0; c < sim.d->ncon; ++c) {
      const int body = sim.m->geom_bodyid[sim.d->contact[c].geom2];
      const std::string name = mj_id2name(sim.m, mjOBJ_BODY, body);
      EXPECT_TRUE(name == "RR_shank" || name == "RL_shank") << name;
      contact_x += 0.5 * sim.d->contact[c].pos[0];
    }
    EXPECT_NEAR(sim.d->subtree_com[3 * 1 + 0], contact_x, 1e-3) << "elevation " << sample.elevation_rad;
    for (double tau : sample.torque_nm) EXPECT_LT(std::abs(tau), robot::kTorqueMaxNm);
  }
}

// runs the simulator from a sample's pose with the trunk pushed, the gain on the true state
// (or none), and says whether the trunk is still within 0.1 rad of its pose after 3 s
bool holds_pose_after_a_push(const UprightSample& sample, bool with_gain) {
  Sim sim;
  std::copy(sample.position.data(), sample.position.data() + sample.position.size(), sim.d->qpos);
  mju_zero(sim.d->qvel, sim.m->nv);
  sim.d->qvel[4] = 0.3;  // a pitch rate kick
  const int ticks = static_cast<int>(3.0 / 0.002);
  for (int tick = 0; tick < ticks; ++tick) {
    UprightStateError error;
    mj_differentiatePos(sim.m, error.data(), 1.0, sample.position.data(), sim.d->qpos);
    for (int i = 0; i < kUprightVelocitySize; ++i) error[kUprightVelocitySize + i] = sim.d->qvel[i];
    const Eigen::Matrix<double, kNumJoints, 1> feedback = sample.gain * error;
    for (std::size_t j = 0; j < kNumJoints; ++j) {
      const double tau = sample.torque_nm[j] - (with_gain ? feedback[static_cast<Eigen::Index>(j)] : 0.0);
      sim.d->ctrl[j] = std::clamp(tau, -robot::kTorqueMaxNm, robot::kTorqueMaxNm);
    }
    mj_step(sim.m, sim.d);
    mj_step(sim.m, sim.d);
  }
  UprightPosition now;
  std::copy(sim.d->qpos, sim.d->qpos + now.size(), now.data());
  return upright_difference(sample.position, now).segment<3>(3).norm() < 0.1;
}

TEST(UprightBalanceDesign, EachGainHoldsItsPoseAgainstAKickThatTopplesItWithoutTheGain) {
  const std::vector<UprightSample>& samples = family();
  for (std::size_t i : {std::size_t{0}, samples.size() / 2, samples.size() - 1}) {
    EXPECT_TRUE(holds_pose_after_a_push(samples[i], true)) << "sample " << i;
    EXPECT_FALSE(holds_pose_after_a_push(samples[i], false)) << "sample " << i;
  }
}

TEST(UprightBalanceDesign, AMissingModelIsRefusedNamingTheFile) {
  try {
    design_upright_balance("/nowhere/dog.xml", UprightDesignConfig{}, 0.002);
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("/nowhere/dog.xml"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace cerebellum
