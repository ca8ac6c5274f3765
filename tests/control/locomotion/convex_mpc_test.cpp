// The convex MPC's model, discretisation and QP against independent computations.
#include "control/locomotion/convex_mpc.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>

#include "control/qp/alglib_qp_solver.hpp"
#include "control/qp/goldfarb_idnani_solver.hpp"

namespace cerebellum {
namespace {

using StateVector = Eigen::Matrix<double, kSrbStates, 1>;

std::array<Eigen::Vector3d, kNumLegs> standing_feet() {
  return {Eigen::Vector3d(0.18, -0.13, -0.25), Eigen::Vector3d(0.18, 0.13, -0.25), Eigen::Vector3d(-0.15, -0.13, -0.25),
          Eigen::Vector3d(-0.15, 0.13, -0.25)};
}

// a robot at rest at height 0.25 asked to stay (or move at vx_ref)
MpcInput standing_input(double vx_ref = 0.0, bool trot = false) {
  MpcInput in;
  in.x0.setZero();
  in.x0[5] = 0.25;
  in.x0[12] = -9.81;
  for (int k = 0; k < kMpcHorizon; ++k) {
    in.x_ref[k] = in.x0;
    in.x_ref[k][3] = vx_ref * 0.03 * (k + 1);
    in.x_ref[k][9] = vx_ref;
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      // trot: FR+RL in stance for the first half of the horizon, FL+RR for the second
      const bool first_pair = leg == 0 || leg == 3;
      in.contact[k][leg] = !trot || (first_pair == (k < 5));
    }
  }
  in.foot_from_com = standing_feet();
  return in;
}

// the MPC's cost of every foot's force at every step (12 per step, world frame): the discretised
// model rolled forward one step at a time, each step's lever arms from where the COM is then
double rollout_cost_of(const MpcInput& in, const Eigen::VectorXd& u) {
  const ConvexMpcConfig config;
  StateVector x = in.x0;
  double cost = 0.0;
  for (int k = 0; k < kMpcHorizon; ++k) {
    std::array<Eigen::Vector3d, kNumLegs> lever = in.foot_from_com;
    for (auto& r : lever) r -= in.com_shift[k];
    Eigen::Matrix<double, kSrbStates, kSrbStates> a, ad;
    Eigen::Matrix<double, kSrbStates, 12> b, bd;
    ConvexMpc::continuous_dynamics(config, in.x0[2], lever, a, b);
    ConvexMpc::discretize(a, b, config.dt_s, ad, bd);
    x = ad * x + bd * u.segment<12>(12 * k);
    for (int s = 0; s < 12; ++s) cost += config.state_weights[s] * std::pow(x[s] - in.x_ref[k][s], 2);
    cost += config.force_weight * u.segment<12>(12 * k).squaredNorm();
  }
  return cost;
}

std::unique_ptr<ConvexMpc> make_mpc() {
  return std::make_unique<ConvexMpc>(ConvexMpcConfig{}, std::make_unique<qp::GoldfarbIdnaniSolver>());
}

TEST(ConvexMpc, DiscretisationMatchesFineRungeKuttaIntegration) {
  Eigen::Matrix<double, kSrbStates, kSrbStates> a, ad;
  Eigen::Matrix<double, kSrbStates, 12> b, bd;
  ConvexMpc::continuous_dynamics(ConvexMpcConfig{}, 0.7, standing_feet(), a, b);
  ConvexMpc::discretize(a, b, 0.03, ad, bd);
  StateVector x;
  x << 0.1, -0.05, 0.7, 0.3, 0.2, 0.25, 0.4, -0.3, 1.0, 0.5, 0.1, -0.2, -9.81;
  Eigen::Matrix<double, 12, 1> u;
  u << 3, 1, 20, -2, 1, 22, 1, -1, 19, 0, 2, 21;
  // independent: RK4 with 3000 steps of the continuous model under constant u
  StateVector y = x;
  const double h = 0.03 / 3000;
  auto f = [&](const StateVector& s) -> StateVector { return a * s + b * u; };
  for (int i = 0; i < 3000; ++i) {
    const StateVector k1 = f(y), k2 = f(y + 0.5 * h * k1), k3 = f(y + 0.5 * h * k2), k4 = f(y + h * k3);
    y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  EXPECT_LT((ad * x + bd * u - y).norm(), 1e-9);
}

TEST(ConvexMpc, ContinuousModelHasGravityMassAndYawRotation) {
  Eigen::Matrix<double, kSrbStates, kSrbStates> a;
  Eigen::Matrix<double, kSrbStates, 12> b;
  ConvexMpc::continuous_dynamics(ConvexMpcConfig{}, 1.5707963267948966, standing_feet(), a, b);
  EXPECT_EQ(a(11, 12), 1.0);
  EXPECT_NEAR(b(9, 0), 1.0 / robot::kMpcMassKg, 1e-12);
  // yaw 90 deg: world wx drives pitch rate with sign -1 through Rz^T
  EXPECT_NEAR(a(1, 6), -1.0, 1e-12);
  // torque of a vertical force at the FR foot about x: r_y * fz / I_xx' (yaw 90 deg swaps x and y inertia)
  EXPECT_NEAR(b(6, 2), -0.13 / 0.17843, 1e-9);
}

TEST(ConvexMpc, StandingStillCarriesTheWeightInsideTheFrictionCone) {
  auto mpc = make_mpc();
  const MpcOutput out = mpc->solve(standing_input());
  ASSERT_EQ(out.status, qp::QpStatus::Solved);
  EXPECT_EQ(out.variables, 120);
  double total_z = 0;
  for (const auto& f : out.forces) {
    total_z += f.z();
    EXPECT_GE(f.z(), 0.0);
    EXPECT_LE(std::abs(f.x()), 0.4 * f.z() + 1e-6);
    EXPECT_LE(std::abs(f.y()), 0.4 * f.z() + 1e-6);
  }
  // the first step carries the weight (the finite horizon makes it lean a little above m g)
  EXPECT_NEAR(total_z, robot::kMpcMassKg * 9.81, 0.1 * robot::kMpcMassKg * 9.81);
  // symmetric left/right; the rear feet, nearer the COM, carry more than the front ones
  EXPECT_NEAR(out.forces[0].z(), out.forces[1].z(), 1e-6);
  EXPECT_GT(out.forces[2].z(), out.forces[0].z());
}

TEST(ConvexMpc, SolutionCostsNoMoreThanStaticEquilibrium) {
  // an independent candidate: every step carries m g split front/rear by the lever arms
  auto mpc = make_mpc();
  const MpcOutput out = mpc->solve(standing_input());
  ASSERT_EQ(out.status, qp::QpStatus::Solved);
  const qp::QpProblem& p = mpc->problem();
  const Eigen::MatrixXd h = p.hessian.selfadjointView<Eigen::Lower>();
  const double weight = robot::kMpcMassKg * 9.81;
  const double front = weight * 0.15 / 0.33 / 2, rear = weight * 0.18 / 0.33 / 2;
  Eigen::VectorXd equilibrium = Eigen::VectorXd::Zero(h.rows());
  for (int k = 0; k < kMpcHorizon; ++k) {
    for (int leg = 0; leg < 4; ++leg) equilibrium[12 * k + 3 * leg + 2] = leg < 2 ? front : rear;
  }
  // the equilibrium holds the reference exactly: only the force penalty remains
  const double equilibrium_cost = 0.5 * equilibrium.dot(h * equilibrium) + p.linear.dot(equilibrium);
  Eigen::VectorXd solution(h.rows());
  // rebuild the solution vector from a second solve through the public interface
  qp::GoldfarbIdnaniSolver solver;
  qp::QpSolution full;
  ASSERT_EQ(solver.solve(p, full), qp::QpStatus::Solved);
  solution = full.x;
  const double solution_cost = 0.5 * solution.dot(h * solution) + p.linear.dot(solution);
  EXPECT_LE(solution_cost, equilibrium_cost + 1e-9);
  EXPECT_NEAR(solution.segment<3>(0).z(), out.forces[0].z(), 1e-9);
}

TEST(ConvexMpc, SwingFeetLoseTheirVariables) {
  auto mpc = make_mpc();
  const MpcOutput out = mpc->solve(standing_input(0.0, true));
  ASSERT_EQ(out.status, qp::QpStatus::Solved);
  EXPECT_EQ(out.variables, 60);
  EXPECT_EQ(mpc->problem().ineq_matrix.rows(), 100);
  EXPECT_EQ(out.forces[1].norm(), 0.0);  // FL in swing now
  EXPECT_EQ(out.forces[2].norm(), 0.0);
  EXPECT_GT(out.forces[0].z(), 20.0);
}

TEST(ConvexMpc, AskingForForwardSpeedPushesForward) {
  auto mpc = make_mpc();
  const MpcOutput out = mpc->solve(standing_input(0.5));
  ASSERT_EQ(out.status, qp::QpStatus::Solved);
  double total_x = 0;
  for (const auto& f : out.forces) total_x += f.x();
  EXPECT_GT(total_x, 1.0);
}

TEST(ConvexMpc, AStandThatHoldsItsPositionPullsADisplacedTrunkBackHarder) {
  // the trunk 3 cm left of its reference: both pull it back, the holding stand (weight 40 on x, y
  // instead of 2) with a larger sideways force
  auto total_y = [](const MpcOutput& out) {
    double y = 0.0;
    for (const auto& f : out.forces) y += f.y();
    return y;
  };
  MpcInput in = standing_input();
  in.x0[4] = 0.03;
  auto mpc = make_mpc();
  const MpcOutput leaning = mpc->solve(in);
  in.hold_position = true;
  const MpcOutput holding = mpc->solve(in);
  ASSERT_EQ(leaning.status, qp::QpStatus::Solved);
  ASSERT_EQ(holding.status, qp::QpStatus::Solved);
  EXPECT_LT(total_y(leaning), 0.0);
  EXPECT_LT(total_y(holding), 3.0 * total_y(leaning));
}

TEST(ConvexMpc, StandsThroughoutOnlyWhenEveryFootIsDownAtEveryStep) {
  EXPECT_TRUE(stands_throughout(standing_input().contact));
  EXPECT_FALSE(stands_throughout(standing_input(0.0, true).contact));
  MpcInput late_lift = standing_input();
  late_lift.contact[kMpcHorizon - 1][2] = false;
  EXPECT_FALSE(stands_throughout(late_lift.contact));
}

TEST(ConvexMpc, AFrontPairStandingAloneRollsTheTrunkLessToTurnAtItsShareOfTheYawWeight) {
  // the front pair alone through the horizon, asked to turn at 1 rad/s: its only yaw lever is
  // sideways force at its feet, which also rolls the trunk over them (here a third less at 0.3)
  MpcInput in = standing_input();
  for (int k = 0; k < kMpcHorizon; ++k) {
    in.contact[k] = {true, true, false, false};
    in.x_ref[k][2] = -1.0 * 0.03 * (k + 1);
    in.x_ref[k][8] = -1.0;
  }
  // the feet's torque about the trunk's forward axis
  const auto roll_torque_nm = [&](const MpcOutput& out) {
    double roll = 0.0;
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) roll += in.foot_from_com[leg].cross(out.forces[leg]).x();
    return roll;
  };
  ConvexMpcConfig full;
  full.lone_pair_yaw_weight_share = 1.0;
  ConvexMpc full_weight(full, std::make_unique<qp::GoldfarbIdnaniSolver>());
  const MpcOutput at_full = full_weight.solve(in);
  const MpcOutput at_share = make_mpc()->solve(in);
  ASSERT_EQ(at_full.status, qp::QpStatus::Solved);
  ASSERT_EQ(at_share.status, qp::QpStatus::Solved);
  EXPECT_LT(std::abs(roll_torque_nm(at_share)), 0.8 * std::abs(roll_torque_nm(at_full)));
  // with a trot's diagonal the share does not apply: the same solution either way
  const MpcOutput trot_full = full_weight.solve(standing_input(0.0, true));
  const MpcOutput trot_share = make_mpc()->solve(standing_input(0.0, true));
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    EXPECT_LT((trot_full.forces[leg] - trot_share.forces[leg]).norm(), 1e-9);
  }
}

TEST(ConvexMpc, GoldfarbIdnaniAgreesWithAlglibOnTheRealProblem) {
  ConvexMpc gi(ConvexMpcConfig{}, std::make_unique<qp::GoldfarbIdnaniSolver>());
  ConvexMpc alglib(ConvexMpcConfig{}, std::make_unique<qp::AlglibQpSolver>());
  for (double vx : {0.0, 0.8}) {
    const MpcOutput a = gi.solve(standing_input(vx, true));
    const MpcOutput b = alglib.solve(standing_input(vx, true));
    ASSERT_EQ(a.status, qp::QpStatus::Solved);
    ASSERT_EQ(b.status, qp::QpStatus::Solved);
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) EXPECT_LT((a.forces[leg] - b.forces[leg]).norm(), 0.05) << leg;
  }
}

TEST(ConvexMpc, QpCostMatchesAStepByStepRolloutWithLeverArmsFollowingTheCom) {
  // a body walking at 0.5 m/s: each step's lever arms are the feet seen from where the COM is then
  auto mpc = make_mpc();
  MpcInput in = standing_input(0.5);
  in.x0[9] = 0.5;
  in.x0[2] = 0.4;
  for (int k = 0; k < kMpcHorizon; ++k) in.com_shift[k] = Eigen::Vector3d(0.5 * 0.03 * k, 0.01 * k, 0.0);
  mpc->build(in);
  const qp::QpProblem& p = mpc->problem();
  const Eigen::MatrixXd h = p.hessian.selfadjointView<Eigen::Lower>();
  auto qp_cost = [&](const Eigen::VectorXd& u) { return 0.5 * u.dot(h * u) + p.linear.dot(u); };
  // independent: roll the discretised model forward one step at a time and add up the cost
  auto rollout_cost = [&](const Eigen::VectorXd& u) { return rollout_cost_of(in, u); };
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> force(-10.0, 30.0);
  Eigen::VectorXd u1(h.rows()), u2(h.rows());
  for (int i = 0; i < h.rows(); ++i) {
    u1[i] = force(rng);
    u2[i] = force(rng);
  }
  // the QP drops the constant term: differences of cost must agree
  const double expected = rollout_cost(u1) - rollout_cost(u2);
  EXPECT_NEAR(qp_cost(u1) - qp_cost(u2), expected, 1e-6 * std::abs(expected));
  // and the shift matters: without it the rollout is a different one
  for (auto& shift : in.com_shift) shift.setZero();
  EXPECT_GT(std::abs(rollout_cost(u1) - rollout_cost(u2) - expected), 1e-3 * std::abs(expected));
}

TEST(ConvexMpc, QpMatchesARolloutWhenSwingFeetLeaveStepsWithFewerForcesOrNone) {
  // the Hessian is built block by block over the steps' kept forces: a trot with a flight step
  // (no force at all) and a step on three feet must still give the rollout's cost
  auto mpc = make_mpc();
  MpcInput in = standing_input(0.8, true);
  in.x0[9] = 0.7;
  in.x0[2] = -0.3;
  in.contact[4] = {false, false, false, false};
  in.contact[7] = {true, true, false, true};
  for (int k = 0; k < kMpcHorizon; ++k) in.com_shift[k] = Eigen::Vector3d(0.7 * 0.03 * k, 0.0, 0.0);
  mpc->build(in);
  const qp::QpProblem& p = mpc->problem();
  // both triangles are filled, and alike
  EXPECT_EQ(p.hessian, p.hessian.transpose());
  const Eigen::MatrixXd& h = p.hessian;
  auto qp_cost = [&](const Eigen::VectorXd& u) { return 0.5 * u.dot(h * u) + p.linear.dot(u); };
  // independent: spread the kept forces over all feet (swing feet push nothing) and roll out
  auto rollout_cost = [&](const Eigen::VectorXd& kept) {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(12 * kMpcHorizon);
    Eigen::Index next = 0;
    for (int k = 0; k < kMpcHorizon; ++k) {
      for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
        if (!in.contact[k][leg]) continue;
        u.segment<3>(12 * k + 3 * static_cast<Eigen::Index>(leg)) = kept.segment<3>(next);
        next += 3;
      }
    }
    EXPECT_EQ(next, kept.size());
    return rollout_cost_of(in, u);
  };
  ASSERT_EQ(h.rows(), 3 * (2 * 8 + 3));  // eight steps on two feet, one on three, one on none
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> force(-10.0, 30.0);
  for (int trial = 0; trial < 3; ++trial) {
    Eigen::VectorXd u1(h.rows()), u2(h.rows());
    for (int i = 0; i < h.rows(); ++i) {
      u1[i] = force(rng);
      u2[i] = force(rng);
    }
    const double expected = rollout_cost(u1) - rollout_cost(u2);
    EXPECT_NEAR(qp_cost(u1) - qp_cost(u2), expected, 1e-6 * std::abs(expected)) << trial;
  }
}

TEST(ConvexMpc, NonFiniteInputIsRefusedWithoutSolving) {
  auto mpc = make_mpc();
  MpcInput in = standing_input();
  in.x0[4] = std::nan("");
  EXPECT_EQ(mpc->solve(in).status, qp::QpStatus::InvalidInput);
  in = standing_input();
  in.foot_from_com[2].x() = INFINITY;
  EXPECT_EQ(mpc->solve(in).status, qp::QpStatus::InvalidInput);
  in = standing_input();
  in.com_shift[4].y() = std::nan("");
  EXPECT_EQ(mpc->solve(in).status, qp::QpStatus::InvalidInput);
}

}  // namespace
}  // namespace cerebellum

namespace cerebellum {
namespace {
// a stand asked to speed up hard along the diagonal: the forces lean as far as the pyramid lets them
MpcInput diagonal_rush_input(FrictionPyramid pyramid) {
  MpcInput in = standing_input();
  for (auto& x : in.x_ref) x[9] = x[10] = 3.0;
  in.pyramid = pyramid;
  return in;
}

double largest_diagonal_share(const MpcOutput& out) {
  double share = 0.0;
  for (const auto& f : out.forces) {
    if (f.z() > 1.0) share = std::max(share, (std::abs(f.x()) + std::abs(f.y())) / f.z());
  }
  return share;
}
}  // namespace

TEST(ConvexMpc, TheDiamondPyramidKeepsEachFootWithinTheFrictionCoefficientAlongTheDiagonal) {
  auto mpc = make_mpc();
  const double mu = ConvexMpcConfig{}.friction;
  const MpcOutput square = mpc->solve(diagonal_rush_input(FrictionPyramid::Square));
  ASSERT_EQ(square.status, qp::QpStatus::Solved);
  // the square's corner reaches mu along each axis at once
  EXPECT_GT(largest_diagonal_share(square), 1.5 * mu);
  const MpcOutput diamond = mpc->solve(diagonal_rush_input(FrictionPyramid::Diamond));
  ASSERT_EQ(diamond.status, qp::QpStatus::Solved);
  EXPECT_LE(largest_diagonal_share(diamond), mu + 1e-6);
  EXPECT_GT(largest_diagonal_share(diamond), 0.9 * mu);  // and it leans as far as that
}

}  // namespace cerebellum
