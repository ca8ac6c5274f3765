#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include <mujoco/mujoco.h>
#include "backend/sim_fixture.hpp"
#include "control/self_righting.hpp"
#include "control/stand_up_controller.hpp"

namespace cerebellum {
namespace {

struct Player final : public MotionController {
  std::vector<JointKeyframe> frames;
  bool active = false;
  double t0 = -1;
  JointArray<double> q0{};
  double kp = 60, kd = 1.5;
  void compute(const RobotState& state, JointCommand& command) override {
    if (!active) { command = JointCommand{}; command.q_des = state.q; command.kd.fill(1.0); return; }
    if (t0 < 0) { t0 = state.time_s; q0 = state.q; }
    double t = state.time_s - t0;
    const JointArray<double>* from = &q0;
    const JointKeyframe* to = &frames.back();
    double f = 1.0;
    for (const auto& k : frames) { if (t < k.duration_s) { to = &k; f = smooth_step(t / k.duration_s); break; } t -= k.duration_s; from = &k.q; }
    for (std::size_t i = 0; i < kNumJoints; ++i) { command.q_des[i] = (*from)[i] + (to->q[i] - (*from)[i]) * f; command.kp[i] = kp; command.kd[i] = kd; command.qd_des[i] = 0; command.tau_ff[i] = 0; }
  }
};

JointKeyframe kf(std::array<double,3> right, std::array<double,3> left, double d) {
  JointKeyframe k; k.duration_s = d;
  for (std::size_t leg = 0; leg < 4; ++leg) { const auto& p = leg_side_sign(leg) < 0 ? right : left; for (int j = 0; j < 3; ++j) k.q[3*leg+j] = p[j]; }
  return k;
}

double env(const char* n, double d) { return std::getenv(n) ? std::atof(std::getenv(n)) : d; }

TEST(RightingDebug, Search) {
  const double roll = env("ROLL", 3.1416);
  const int trials = static_cast<int>(env("TRIALS", 200));
  const std::array<double,3> fold{0, 1.396, -2.356};
  std::mt19937 rng(static_cast<unsigned>(env("SEED", 1)));
  std::uniform_real_distribution<double> ab(-0.68, 0.68), hp(-0.9, 2.75), kn(-2.4, -0.55), du(0.05, 0.35);
  for (int trial = 0; trial < trials; ++trial) {
    std::array<std::array<double,3>,6> P;
    for (auto& x : P) x = {ab(rng), hp(rng), kn(rng)};
    const double d3 = du(rng), d4 = du(rng);
    Player p;
    p.kp = 100;
    testing::LockstepSim sim(testing::sim_config(0.3), p);
    const Eigen::Quaterniond q(Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()));
    sim.backend.set_base_pose({0, 0, 0.3}, {q.w(), q.x(), q.y(), q.z()});
    sim.run_for(1.5);
    p.frames = {kf(fold, fold, 0.5), kf(P[0], P[1], 0.6), kf(P[2], P[3], d3), kf(P[4], P[5], d4), kf(P[4], P[5], 1.5)};
    p.active = true;
    sim.run_for(4.0);
    const RobotState& s = sim.loop.last_cycle().state;
    if (std::abs(s.rpy.x()) < 1.2)
    std::printf("trial %d final roll %.2f pitch %.2f | %.2f %.2f %.2f / %.2f %.2f %.2f | %.2f %.2f %.2f / %.2f %.2f %.2f d %.2f | %.2f %.2f %.2f / %.2f %.2f %.2f d %.2f\n", trial, s.rpy.x(), s.rpy.y(),
      P[0][0],P[0][1],P[0][2],P[1][0],P[1][1],P[1][2],P[2][0],P[2][1],P[2][2],P[3][0],P[3][1],P[3][2],d3,P[4][0],P[4][1],P[4][2],P[5][0],P[5][1],P[5][2], d4);
  }
}

}  // namespace
}  // namespace cerebellum
