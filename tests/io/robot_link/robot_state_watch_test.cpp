// What every real robot's state stream must pass, on the MC's types and without a transport: the
// 20 ms link watch over the receiver's listening window, states that repeat or jump, the stop on a
// motor error.
#include "io/robot_link/robot_state_watch.hpp"

#include <gtest/gtest.h>

#include "core/robot_model.hpp"
#include "io/robot_link/lying_robot.hpp"

namespace cerebellum {
namespace {

constexpr double kLinkTimeoutS = 0.020;

// the watch with fresh joints and IMU at time now_s on the link's clock
RobotStateWatch heard_watch(double now_s = 0.0) {
  RobotStateWatch watch{kLinkTimeoutS};
  watch.take_joints(lying_joints(), now_s);
  watch.take_imu(ImuReading{}, now_s);
  return watch;
}

TEST(RobotStateWatch, ASilenceWhileTheReceiverItselfWasPausedIsNotALostLink) {
  RobotStateWatch watch = heard_watch(1.000);
  // the receiving thread paused (descheduled, the machine stalled) and listens again since 1.025 s
  EXPECT_EQ(watch.frame(listened(1.030, 1.025), 5.0).motor_faults[0], kMotorOk) << "5 ms of listening, not 30 ms";
  EXPECT_FALSE(watch.status().link_lost);
  EXPECT_TRUE(watch.frame(listened(1.046, 1.025), 5.002).motor_faults[0] & kMotorDisconnected)
      << "21 ms of listening without a word: lost";
  EXPECT_TRUE(watch.frame(listened(1.050, 1.048), 5.004).motor_faults[0] & kMotorDisconnected)
      << "once lost, a pause of the receiver does not bring the link back: only a fresh message does";
}

TEST(RobotStateWatch, AfterAStallOfTheWholeMachineTheLinkIsJudgedOnlyOnceTheReceiverHasListenedAgain) {
  ListeningClock receiver(0.005);
  RobotStateWatch watch = heard_watch(1.000);
  receiver.step(1.000);
  receiver.step(1.001);
  // the machine stalls 30 ms; the loop's thread runs first when it resumes, before the receiver
  // has taken what the robot sent meanwhile: its clock reads 1.031, the receiver's last step 1.001
  EXPECT_EQ(watch.frame(receiver.window(), 5.0).motor_faults[0], kMotorOk)
      << "30 ms on the reader's clock, but the receiver was not listening";
  receiver.step(1.031);
  EXPECT_EQ(watch.frame(receiver.window(), 5.002).motor_faults[0], kMotorOk) << "it listens again from 1.031 s";
  for (double step_s = 1.032; step_s < 1.052; step_s += 0.001) receiver.step(step_s);  // listening, nothing comes
  EXPECT_TRUE(watch.frame(receiver.window(), 5.004).motor_faults[0] & kMotorDisconnected)
      << "over 20 ms of listening without a word: lost";
}

TEST(RobotStateWatch, AStreamThatOnlyRepeatsItsLastStateIsALostLinkAfterTheTimeout) {
  RobotStateWatch watch = heard_watch(1.000);
  // the robot's joints keep coming, but each equal to the one before in every value: a stuck sender
  JointReading stuck = lying_joints();
  for (double t_s = 1.002; t_s < 1.030; t_s += 0.002) {
    watch.take_joints(stuck, t_s);
    watch.take_imu(live_imu(t_s), t_s);  // the IMU lives
  }
  EXPECT_TRUE(watch.frame(listened(1.030), 5.0).motor_faults[0] & kMotorDisconnected)
      << "30 ms of repeated joints: no fresh joint state";
  EXPECT_GE(watch.status().repeated_states, 14u);
  stuck.qd[2] = 1e-6;  // any value changed: news again (and, the link being lost, an IMU sample after it)
  watch.take_joints(stuck, 1.031);
  watch.take_imu(live_imu(1.031), 1.031);
  EXPECT_EQ(watch.frame(listened(1.031), 5.002).motor_faults[0], kMotorOk);
  EXPECT_EQ(watch.status().jumped_states, 0u);
}

TEST(RobotStateWatch, AnIdenticalImuStateIsNotFreshEither) {
  RobotStateWatch watch = heard_watch(1.000);
  for (double t_s = 1.002; t_s < 1.030; t_s += 0.002) {
    watch.take_joints(live_joints(t_s), t_s);
    watch.take_imu(ImuReading{}, t_s);  // the very sample heard_client gave, again and again
  }
  EXPECT_TRUE(watch.frame(listened(1.030), 5.0).motor_faults[0] & kMotorDisconnected);
}

TEST(RobotStateWatch, AJointAngleThatJumpsFurtherThanAJointCanMoveIsRefusedUntilTheStateIsPlausibleAgain) {
  RobotStateWatch watch = heard_watch(1.000);
  JointReading jumped = lying_joints();
  // 2 ms after the last state: a joint may move 2 x 30.5 rad/s x 2 ms + 5 deg = 0.209 rad
  EXPECT_NEAR(joint_step_limit_rad(0.002), 2.0 * robot::kNoLoadSpeedRadS * 0.002 + robot::deg(5.0), 1e-12);
  jumped.q[7] += 0.20;  // within
  watch.take_joints(jumped, 1.002);
  EXPECT_EQ(watch.status().jumped_states, 0u);
  EXPECT_DOUBLE_EQ(watch.frame(listened(1.002), 5.0).q[7], jumped.q[7]) << "taken";
  jumped.q[4] += 3.0;  // an encoder that wrapped
  watch.take_joints(jumped, 1.004);
  EXPECT_EQ(watch.status().jumped_states, 1u);
  EXPECT_NEAR(watch.status().last_jump_rad, 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(watch.frame(listened(1.004), 5.002).q[4], lying_joints().q[4]) << "refused: the old angle stays";
  // the angle stays where it jumped to: compared with the last state taken, it keeps being refused
  // until the link watch calls it lost
  for (double t_s = 1.006; t_s < 1.026; t_s += 0.002) {
    jumped.qd[0] = t_s;  // otherwise live
    watch.take_joints(jumped, t_s);
  }
  EXPECT_TRUE(watch.frame(listened(1.026), 5.004).motor_faults[0] & kMotorDisconnected);
  EXPECT_GE(watch.status().jumped_states, 10u);
}

TEST(RobotStateWatch, AMotorErrorStopsTheClientEvenInAStateRefusedAsAJump) {
  RobotStateWatch watch = heard_watch(1.000);
  JointReading broken = lying_joints();
  broken.q[1] += 2.0;
  broken.motor_faults[1] = kMotorErrorBits & ~(kMotorErrorBits - 1);  // its lowest error bit
  watch.take_joints(broken, 1.002);
  EXPECT_EQ(watch.status().jumped_states, 1u);
  EXPECT_TRUE(watch.status().stopped);
  EXPECT_EQ(watch.status().error_motors, 1u << 1);
}

TEST(RobotStateWatch, ARobotNeverHeardIsALostLink) {
  RobotStateWatch watch{kLinkTimeoutS};
  EXPECT_TRUE(watch.frame(listened(0.0), 0.0).motor_faults[0] & kMotorDisconnected);
  EXPECT_EQ(watch.status().link_losses, 0u) << "never heard is not a loss";
}

}  // namespace
}  // namespace cerebellum
