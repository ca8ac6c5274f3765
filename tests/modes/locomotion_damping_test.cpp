// Mode 11 when its MPC keeps failing: the walking gait damps the joints and the mode says so, which
// the state machine reports as switch_status 3 (EDAMP). The same robot with a working solver
// keeps walking and does not.
#include <gtest/gtest.h>

#include <memory>

#include "control/qp/failing_solver.hpp"
#include "control/qp/goldfarb_idnani_solver.hpp"
#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"
#include "modes/locomotion_mode.hpp"
#include "modes/walking_gaits.hpp"

namespace cerebellum {
namespace {

// a robot standing still at the default height, as the estimator reports it
RobotState standing_robot() {
  RobotState state;
  state.valid = true;
  state.q = robot::whole_body_pose(robot::kStandPose);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const std::size_t j = leg * kJointsPerLeg;
    state.foot_position_body[leg] = foot_position_in_body(leg, Vec3(state.q[j], state.q[j + 1], state.q[j + 2]));
    state.contact[leg] = 1.0;
  }
  state.height_m = -state.foot_position_body[0].z();
  state.position_world = Eigen::Vector3d(0.0, 0.0, state.height_m);
  return state;
}

struct TrottingRobot {
  explicit TrottingRobot(std::unique_ptr<qp::QpSolver> solver) : walking(WalkingGaitsConfig{}, std::move(solver)) {
    gaits.add(3, walking);
    HighLevelCommand trot;
    trot.mode = static_cast<int>(ModeId::Locomotion);
    trot.gait_id = 3;
    EXPECT_EQ(locomotion.check(trot), nullptr);
    locomotion.enter(state, trot);
  }
  // runs the mode for a while on the same state; returns the last joint command
  JointCommand run(double seconds) {
    JointCommand command;
    for (double t = 0.0; t < seconds; t += 0.002) {
      locomotion.run(state, command);
      state.time_s += 0.002;
    }
    return command;
  }
  RobotState state = standing_robot();
  GaitRegistry gaits;
  WalkingGaits walking;
  LocomotionMode locomotion{gaits};
};

TEST(LocomotionDamping, AWalkingGaitWhoseMpcKeepsFailingDampsTheJointsAndReportsIt) {
  TrottingRobot robot(std::make_unique<testing::FailingSolver>());
  const JointCommand command = robot.run(0.3);
  EXPECT_TRUE(robot.locomotion.damping_protection());
  for (std::size_t j = 0; j < kNumJoints; ++j) {
    EXPECT_EQ(command.kp[j], 0.0);
    EXPECT_EQ(command.kd[j], WalkingGaitsConfig{}.failure_damping_kd);
  }
}

TEST(LocomotionDamping, AWalkingGaitWithAWorkingMpcDoesNotReportDamping) {
  TrottingRobot robot(std::make_unique<qp::GoldfarbIdnaniSolver>());
  robot.run(0.3);
  EXPECT_FALSE(robot.locomotion.damping_protection());
}

}  // namespace
}  // namespace cerebellum
