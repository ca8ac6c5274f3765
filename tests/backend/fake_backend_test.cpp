// The MuJoCo backend's motor drivers and the fake backend obey the same motor law and limits.
#include <gtest/gtest.h>

#include "backend/fake_backend.hpp"
#include "backend/sim_fixture.hpp"

namespace cerebellum {
namespace {

TEST(MujocoDrivers, SaturateAtTwelveNewtonMetres) {
  MujocoBackend backend(testing::sim_config(1.0));
  JointCommand command;
  const SensorFrame before = backend.read();
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    command.q_des[i] = before.q[i] + 1.0;  // kp * 1 rad = 200 N m requested
    command.kp[i] = 200.0;
  }
  backend.write(command);
  backend.advance(0.001);
  const SensorFrame after = backend.read();
  for (std::size_t i = 0; i < kNumJoints; ++i) EXPECT_DOUBLE_EQ(after.tau[i], 12.0) << i;
}

TEST(MujocoDrivers, ApplyTheMotorLawAtEveryPhysicsStep) {
  MujocoBackend backend(testing::sim_config(1.0));
  JointCommand command;
  command.kd.fill(0.5);
  command.tau_ff.fill(0.3);
  backend.write(command);
  backend.advance(0.002);
  const SensorFrame frame = backend.read();
  // the torque of the last step used the joint velocity of that step (before its integration)
  for (std::size_t i = 0; i < kNumJoints; ++i) EXPECT_NEAR(frame.tau[i], 0.3 - 0.5 * frame.qd[i], 0.05) << i;
}

TEST(MujocoDrivers, NonFiniteCommandGivesNoTorque) {
  MujocoBackend backend(testing::sim_config(1.0));
  JointCommand command;
  command.kp.fill(10.0);
  command.q_des[4] = std::nan("");
  backend.write(command);
  backend.advance(0.001);
  EXPECT_EQ(backend.read().tau[4], 0.0);
}

TEST(FakeBackend, JointsFollowThePdLawTowardTheTarget) {
  FakeBackend backend;
  JointCommand command;
  command.q_des.fill(0.5);
  command.kp.fill(20.0);
  command.kd.fill(3.0);
  for (int i = 0; i < 3000; ++i) {
    backend.write(command);
    backend.advance(0.002);
  }
  for (double q : backend.read().q) EXPECT_NEAR(q, 0.5, 1e-3);
  EXPECT_NEAR(backend.time_s(), 6.0, 1e-9);
}

}  // namespace
}  // namespace cerebellum
