// The two-leg stand's state against MuJoCo's own kinematics of the robot model (an independent
// implementation): position differences as mj_differentiatePos gives them, the shanks' roll angle
// from the shank bodies' orientation, and the trunk's velocity over a rolling foot from the
// velocity MuJoCo gives the foot's centre.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <Eigen/Geometry>
#include <random>
#include <string>
#include <vector>

#include "control/upright/upright_state.hpp"
#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"
#include "mujoco_model.hpp"

namespace cerebellum {
namespace {

using Model = testing::MujocoModel;

UprightPosition random_position(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  UprightPosition q;
  q.head<3>() = Eigen::Vector3d(u(rng), u(rng), 0.3 + 0.1 * u(rng));
  const Eigen::Quaterniond turn = Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized();
  q.segment<4>(3) << turn.w(), turn.x(), turn.y(), turn.z();
  for (int j = 0; j < 12; ++j) q[7 + j] = 0.8 * u(rng);
  return q;
}

TEST(UprightDifference, IsWhatMujocoCallsThePositionDifference) {
  Model model;
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    const UprightPosition a = random_position(rng);
    const UprightPosition b = random_position(rng);
    UprightVelocity expected;
    mj_differentiatePos(model.m, expected.data(), 1.0, a.data(), b.data());
    EXPECT_LT((upright_difference(a, b) - expected).cwiseAbs().maxCoeff(), 1e-9) << "trial " << trial;
  }
}

// puts the model at q (MuJoCo's coordinates) with velocities v and runs its kinematics
void place(Model& model, const UprightPosition& q, const UprightVelocity& v) {
  std::copy(q.data(), q.data() + q.size(), model.d->qpos);
  std::copy(v.data(), v.data() + v.size(), model.d->qvel);
  mj_forward(model.m, model.d);
}

RobotState robot_state(const UprightPosition& q, const UprightVelocity& v) {
  RobotState state;
  state.orientation = upright_orientation(q);
  state.omega_body = v.segment<3>(3);
  for (std::size_t j = 0; j < kNumJoints; ++j) {
    state.q[j] = q[7 + static_cast<Eigen::Index>(j)];
    state.qd[j] = v[6 + static_cast<Eigen::Index>(j)];
  }
  return state;
}

TEST(HindShankRollAngle, IsTheShanksTurnAboutTheWorldsLateralAxis) {
  Model model;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    UprightPosition q = random_position(rng);
    // a trunk turned about the lateral axis only, the abad joints near zero: the shanks' turn is
    // then one angle about that axis
    const Eigen::Quaterniond pitch(Eigen::AngleAxisd(1.5 * u(rng), Eigen::Vector3d::UnitY()));
    q.segment<4>(3) << pitch.w(), pitch.x(), pitch.y(), pitch.z();
    q[7 + 6] = q[7 + 9] = 0.0;
    q[7 + 8] = -1.0 - 0.5 * std::abs(u(rng));
    q[7 + 11] = q[7 + 8];
    q[7 + 10] = q[7 + 7];
    place(model, q, UprightVelocity::Zero());
    double expected = 0.0;
    for (const char* shank : {"RR_shank", "RL_shank"}) {
      const mjtNum* x = model.d->xmat + 9 * mj_name2id(model.m, mjOBJ_BODY, shank);
      expected += 0.5 * std::atan2(x[2], x[8]);  // R(0,2), R(2,2): the turn about y
    }
    JointArray<double> joints{};
    for (std::size_t j = 0; j < kNumJoints; ++j) joints[j] = q[7 + static_cast<Eigen::Index>(j)];
    EXPECT_NEAR(hind_shank_roll_angle(upright_orientation(q).toRotationMatrix(), joints), expected, 1e-9);
  }
}

TEST(TrunkVelocityOverRollingFoot, LeavesTheFootsContactPointStillInMujoco) {
  Model model;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const UprightPosition q = random_position(rng);
    UprightVelocity v;
    for (int i = 0; i < v.size(); ++i) v[i] = 2.0 * u(rng);
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      const Vec3 q_leg(q[7 + 3 * leg], q[7 + 3 * leg + 1], q[7 + 3 * leg + 2]);
      const Vec3 qd_leg(v[6 + 3 * leg], v[6 + 3 * leg + 1], v[6 + 3 * leg + 2]);
      const Eigen::Matrix3d r = upright_orientation(q).toRotationMatrix();
      v.head<3>() = trunk_velocity_over_rolling_foot(leg, r, v.segment<3>(3), q_leg, qd_leg);
      place(model, q, v);
      // the velocity of the shank's material point at the bottom of the foot sphere
      const int shank = mj_name2id(model.m, mjOBJ_BODY, (std::string(kLegNames[leg]) + "_shank").c_str());
      const mjtNum* centre =
          model.d->site_xpos + 3 * mj_name2id(model.m, mjOBJ_SITE, (std::string(kLegNames[leg]) + "_foot").c_str());
      mjtNum bottom[3] = {centre[0], centre[1], centre[2] - robot::kFootRadius};
      // MuJoCo's translational Jacobian of that point on the shank, times the velocities
      std::vector<mjtNum> jacp(3 * model.m->nv);
      mj_jac(model.m, model.d, jacp.data(), nullptr, bottom, shank);
      Eigen::Vector3d point = Eigen::Vector3d::Zero();
      for (int k = 0; k < 3; ++k) {
        for (int i = 0; i < model.m->nv; ++i) point[k] += jacp[k * model.m->nv + i] * v[i];
      }
      EXPECT_LT(point.norm(), 1e-6) << "trial " << trial << " leg " << leg;
    }
  }
}

TEST(UprightState, PutsTheTrunkWhereMujocoHasItOverTheHindFeet) {
  Model model;
  std::mt19937 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    const UprightPosition q = random_position(rng);
    place(model, q, UprightVelocity::Zero());
    Eigen::Vector3d feet = Eigen::Vector3d::Zero();
    for (const char* site : {"RR_foot", "RL_foot"}) {
      const mjtNum* p = model.d->site_xpos + 3 * mj_name2id(model.m, mjOBJ_SITE, site);
      feet += 0.5 * Eigen::Vector3d(p[0], p[1], p[2]);
    }
    JointArray<double> joints{};
    for (std::size_t j = 0; j < kNumJoints; ++j) joints[j] = q[7 + static_cast<Eigen::Index>(j)];
    const Eigen::Matrix3d r = upright_orientation(q).toRotationMatrix();
    // the design's origin: the feet's centres at x = radius * (roll angle - origin)
    const double origin_rad = hind_shank_roll_angle(r, joints) - feet.x() / robot::kFootRadius;
    RobotState state = robot_state(q, UprightVelocity::Zero());
    // the heading frame is the world's when the yaw is taken as 0; the state's yaw removes none
    const UprightState s = upright_state(state, 0.0, origin_rad, feet.z());
    // the design's origin is under the feet's midpoint: the trunk is as far from it as in MuJoCo
    EXPECT_NEAR(s.position.x(), q.x(), 1e-9) << "trial " << trial;
    EXPECT_NEAR(s.position.y(), q.y() - feet.y(), 1e-9) << "trial " << trial;
    EXPECT_NEAR(s.position.z(), q.z(), 1e-9) << "trial " << trial;
  }
}

}  // namespace
}  // namespace cerebellum
