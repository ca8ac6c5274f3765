// The standing controllers run every tick without touching the heap (after their first tick).
#include <gtest/gtest.h>

#include "control/qp/allocation_counter.hpp"
#include "control/qp_stand.hpp"
#include "control/self_righting.hpp"
#include "core/leg_kinematics.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

// a robot standing level at 0.235 m on its four feet
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

TEST(StandAllocation, QpStandTicksDoNotAllocateWhileALegGoesUpAndDown) {
  QpStand stand;
  RobotState state = standing_state();
  JointCommand command;
  stand.start(state);
  QpStandGoal goal;
  goal.pose.rpy = {0.1, 0.05, 0.0};
  goal.pose.position = {0.0, 0.0, 0.24};
  goal.lifted_leg = 2;
  goal.lifted_foot_offset = {0.0, 0.0, 0.08};
  stand.set_goal(goal, PoseSpeed{});
  stand.compute(state, command);
  long allocations = 0;
  {
    qp::fixtures::AllocationCounter counter;
    // through the shift, the unload (3 then 4 loaded feet alternate in the QP) and the lift
    for (int i = 0; i < 1000; ++i) {
      state.time_s += 0.002;
      stand.compute(state, command);
    }
    allocations = counter.count();
  }
  EXPECT_EQ(allocations, 0);
}

TEST(StandAllocation, SelfRightingTicksDoNotAllocate) {
  SelfRighting righting;
  RobotState state = standing_state();
  JointCommand command;
  righting.start(BodyRest::OnLeftSide);
  righting.compute(state, command);
  long allocations = 0;
  {
    qp::fixtures::AllocationCounter counter;
    righting.start(BodyRest::OnRightSide);  // keyframes fit the reserved capacity
    for (int i = 0; i < 2000; ++i) {
      state.time_s += 0.002;
      righting.compute(state, command);
    }
    allocations = counter.count();
  }
  EXPECT_EQ(allocations, 0);
  EXPECT_TRUE(righting.done());
}

}  // namespace
}  // namespace cerebellum
