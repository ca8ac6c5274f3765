// Cost of one control tick of the standing controllers: the QP stand (wrench PID, 12-variable
// force QP, joint torques) on four and on three feet, and the force QP alone.
#include <benchmark/benchmark.h>

#include "control/force_distribution.hpp"
#include "control/qp_stand.hpp"
#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

RobotState standing_state() {
  RobotState state;
  state.valid = true;
  state.contact = {1, 1, 1, 1};
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const Eigen::Vector3d foot = hip_position(leg) + Eigen::Vector3d(0.0, leg_side_sign(leg) * robot::kAbadLength,
                                                                     -(0.235 - robot::kFootRadius));
    const LegIkResult ik = inverse_kinematics_in_body(leg, foot);
    for (std::size_t k = 0; k < kJointsPerLeg; ++k) state.q[3 * leg + k] = ik.q[static_cast<Eigen::Index>(k)];
    state.foot_position_body[leg] = foot;
  }
  return state;
}

// one QP stand tick; range(0) = 1 holds a leg in the air (three loaded feet)
void BM_QpStandTick(benchmark::State& bench) {
  QpStand stand;
  RobotState state = standing_state();
  JointCommand command;
  stand.start(state);
  QpStandGoal goal;
  goal.pose.position = {0.0, 0.0, 0.235};
  goal.lifted_leg = bench.range(0) == 1 ? 0 : SupportSequence::kNoLeg;
  stand.set_goal(goal, PoseSpeed{});
  // run the leg change to its end first
  for (int i = 0; i < 1000; ++i) {
    state.time_s += 0.002;
    stand.compute(state, command);
  }
  for (auto _ : bench) {
    state.time_s += 0.002;
    stand.compute(state, command);
    benchmark::DoNotOptimize(command.tau_ff.data());
  }
}
BENCHMARK(BM_QpStandTick)->Arg(0)->Arg(1);

void BM_ForceDistribution(benchmark::State& bench) {
  ForceDistribution distribution;
  const std::array<Eigen::Vector3d, kNumLegs> feet{
      Eigen::Vector3d(0.17, -0.13, -0.24), Eigen::Vector3d(0.17, 0.13, -0.24), Eigen::Vector3d(-0.17, -0.13, -0.24),
      Eigen::Vector3d(-0.17, 0.13, -0.24)};
  const std::array<double, kNumLegs> limits{150, 150, 150, 150};
  Vector6d wrench;
  wrench << 3.0, -2.0, 85.0, 0.5, -0.8, 0.2;
  std::array<Eigen::Vector3d, kNumLegs> forces{};
  for (auto _ : bench) {
    benchmark::DoNotOptimize(distribution.solve(feet, limits, wrench, forces));
  }
}
BENCHMARK(BM_ForceDistribution);

}  // namespace
}  // namespace cerebellum

BENCHMARK_MAIN();
