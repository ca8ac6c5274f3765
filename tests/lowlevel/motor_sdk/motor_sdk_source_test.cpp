// The MC side of the motor SDK without sockets: every err_flag bit, the activation, the clamps
// and the rejection of bad frames, driven tick by tick in robot time.
#include "lowlevel/motor_sdk/motor_sdk_source.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

constexpr double kTickS = 0.002;
double tick_time(int k) { return k * kTickS; }

JointCommand pose_frame(const JointArray<double>& q, double kp, double kd) {
  JointCommand frame;
  frame.q_des = q;
  frame.kp.fill(kp);
  frame.kd.fill(kd);
  return frame;
}

// a source driven the way the loop drives it: frames stamped with robot time, then compute
class SourceRig {
 public:
  explicit SourceRig(const MotorSdkParameters& parameters = {}) : source(parameters) {
    state.valid = true;
    state.q = robot::whole_body_pose(robot::kLyingPose);
  }

  void push(const JointCommand& frame, double received_s) {
    ASSERT_EQ(source.mailbox().push(frame, received_s), PushResult::Accepted);
  }
  const JointCommand& tick(double now_s) {
    state.time_s = now_s;
    source.compute(state, command);
    return command;
  }
  // the first frame (all zero) arrives at t and the arbiter latches the source
  void enter(double t) {
    push(JointCommand{}, t);
    ASSERT_TRUE(source.wants_control());
    state.time_s = t;
    source.on_latched(state);
    tick(t);
  }
  // all-zero frames every tick from tick k until bit1 clears; returns the tick it cleared on
  int activate(int k) {
    for (;; ++k) {
      push(JointCommand{}, tick_time(k));
      tick(tick_time(k));
      if ((err_flag() & kMotorSdkCommandLost) == 0) return k;
      if (k > 100000) return -1;
    }
  }
  std::uint16_t err_flag() const { return source.status().err_flag; }

  MotorSdkSource source;
  RobotState state;
  JointCommand command;
};

TEST(MotorSdkSource, WantsControlOnlyWithAFramePending) {
  SourceRig rig;
  EXPECT_FALSE(rig.source.wants_control());
  rig.push(JointCommand{}, 0.0);
  EXPECT_TRUE(rig.source.wants_control());
}

TEST(MotorSdkSource, EntersInMotorModeWithBit1AndDamping) {
  SourceRig rig;
  EXPECT_FALSE(rig.source.status().motor_mode);
  rig.enter(0.0);
  EXPECT_TRUE(rig.source.status().motor_mode);
  EXPECT_EQ(rig.err_flag(), kMotorSdkCommandLost);
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    EXPECT_EQ(rig.command.kp[i], 0.0);
    EXPECT_EQ(rig.command.kd[i], 4.0);
    EXPECT_EQ(rig.command.tau_ff[i], 0.0);
  }
}

TEST(MotorSdkSource, ZeroFramesClearBit1OnlyAfterTwoSecondsOfLying) {
  SourceRig rig;
  rig.enter(0.0);
  const int cleared_at = rig.activate(1);
  // bit1 was raised at 0 s; the first zero frame at >= 2 s clears it
  EXPECT_EQ(cleared_at, 1000);
  EXPECT_EQ(rig.err_flag(), 0);
  // activated but still all-zero: the motors are limp
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    EXPECT_EQ(rig.command.kp[i], 0.0);
    EXPECT_EQ(rig.command.kd[i], 0.0);
  }
}

TEST(MotorSdkSource, WhileLostDampsForTwoAndAHalfSecondsThenGoesLimpAndIgnoresCommands) {
  SourceRig rig;
  rig.enter(0.0);
  const JointCommand stand = pose_frame(robot::whole_body_pose(robot::kStandPose), 60.0, 2.0);
  for (int k = 1; k <= 1500; ++k) {
    rig.push(stand, tick_time(k));  // a client that never sends the activation frames
    rig.tick(tick_time(k));
    const double expected_kd = tick_time(k) < 2.5 ? 4.0 : 0.0;
    ASSERT_EQ(rig.command.kd[0], expected_kd) << "t=" << tick_time(k);
    ASSERT_EQ(rig.command.kp[0], 0.0);
  }
  EXPECT_EQ(rig.err_flag() & kMotorSdkCommandLost, kMotorSdkCommandLost);
  EXPECT_EQ(rig.source.counters().frames_ignored_while_lost, 1500u);
}

TEST(MotorSdkSource, ActiveFrameIsExecutedAsSent) {
  SourceRig rig;
  rig.enter(0.0);
  int k = rig.activate(1) + 1;
  JointCommand frame = pose_frame(rig.state.q, 20.0, 1.0);
  frame.qd_des.fill(0.5);
  frame.tau_ff.fill(-0.25);
  rig.push(frame, tick_time(k));
  rig.tick(tick_time(k));
  EXPECT_EQ(rig.err_flag(), 0);
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    EXPECT_EQ(rig.command.q_des[i], frame.q_des[i]);
    EXPECT_EQ(rig.command.qd_des[i], 0.5);
    EXPECT_EQ(rig.command.kp[i], 20.0);
    EXPECT_EQ(rig.command.kd[i], 1.0);
    EXPECT_EQ(rig.command.tau_ff[i], -0.25);
  }
}

TEST(MotorSdkSource, GapOverTenMillisecondsSetsBit0AndDecaysTheCommand) {
  SourceRig rig;
  rig.enter(0.0);
  const int k0 = rig.activate(1) + 1;
  JointCommand frame = pose_frame(rig.state.q, 20.0, 1.0);
  frame.q_des[2] += 0.1;
  frame.qd_des.fill(4.0);
  frame.tau_ff.fill(2.0);
  rig.push(frame, tick_time(k0));
  rig.tick(tick_time(k0));
  // 10 ms after the frame: still on time
  rig.tick(tick_time(k0 + 5));
  EXPECT_EQ(rig.err_flag() & kMotorSdkCommandLate, 0);
  EXPECT_DOUBLE_EQ(rig.command.tau_ff[0], 2.0);
  // 20 ms: late, everything scaled by 10/20
  rig.tick(tick_time(k0 + 10));
  EXPECT_EQ(rig.err_flag(), kMotorSdkCommandLate);
  EXPECT_NEAR(rig.command.qd_des[0], 2.0, 1e-9);
  EXPECT_NEAR(rig.command.tau_ff[0], 1.0, 1e-9);
  EXPECT_NEAR(rig.command.q_des[2], rig.state.q[2] + 0.05, 1e-9);
  EXPECT_EQ(rig.command.kp[2], 20.0);
  // a fresh frame ends the warning and restores the full command
  rig.push(frame, tick_time(k0 + 11));
  rig.tick(tick_time(k0 + 11));
  EXPECT_EQ(rig.err_flag(), 0);
  EXPECT_DOUBLE_EQ(rig.command.tau_ff[0], 2.0);
}

TEST(MotorSdkSource, GapOverHalfASecondSetsBit1AndOnlyZeroFramesRecover) {
  SourceRig rig;
  rig.enter(0.0);
  const int k0 = rig.activate(1) + 1;
  const JointCommand hold = pose_frame(rig.state.q, 20.0, 1.0);
  rig.push(hold, tick_time(k0));
  rig.tick(tick_time(k0));
  rig.tick(tick_time(k0 + 250));  // 500 ms: late, not lost
  EXPECT_EQ(rig.err_flag(), kMotorSdkCommandLate);
  rig.tick(tick_time(k0 + 251));  // 502 ms: lost
  EXPECT_EQ(rig.err_flag() & kMotorSdkCommandLost, kMotorSdkCommandLost);
  EXPECT_EQ(rig.command.kd[0], 4.0);
  EXPECT_EQ(rig.command.kp[0], 0.0);
  EXPECT_EQ(rig.source.counters().commands_lost, 1u);

  // the client comes back at 600 ms with its old command: ignored
  int k = k0 + 300;
  for (; k < k0 + 400; ++k) {
    rig.push(hold, tick_time(k));
    rig.tick(tick_time(k));
  }
  EXPECT_EQ(rig.err_flag() & kMotorSdkCommandLost, kMotorSdkCommandLost);
  EXPECT_EQ(rig.command.kp[0], 0.0);
  // zero frames clear it once bit1 has been set for 2 s (raised at tick k0 + 251)
  const int cleared_at = rig.activate(k);
  EXPECT_EQ(cleared_at, k0 + 251 + 1000);
  EXPECT_EQ(rig.err_flag() & kMotorSdkCommandLost, 0);
}

TEST(MotorSdkSource, FirstZeroFrameAfterLongSilenceDoesNotClear) {
  SourceRig rig;
  rig.enter(0.0);
  // silence for 3 s, then one zero frame: it does not follow a frame within 500 ms
  rig.push(JointCommand{}, 3.0);
  rig.tick(3.0);
  EXPECT_EQ(rig.err_flag() & kMotorSdkCommandLost, kMotorSdkCommandLost);
  rig.push(JointCommand{}, 3.002);
  rig.tick(3.002);
  EXPECT_EQ(rig.err_flag() & kMotorSdkCommandLost, 0);
}

TEST(MotorSdkSource, ThirtyDegreeJumpLeadsTheMeasuredAngleByTwelveDegreesEveryTick) {
  SourceRig rig;
  rig.enter(0.0);
  int k = rig.activate(1) + 1;
  const double knee = rig.state.q[2];
  const double step = robot::deg(12.0);
  JointCommand frame = pose_frame(rig.state.q, 20.0, 1.0);
  frame.q_des[2] = knee + robot::deg(30.0);
  // the joint does not move: every tick the target stays 12 deg ahead of it, with bit4
  for (int n = 1; n <= 3; ++n) {
    rig.push(frame, tick_time(k));
    rig.tick(tick_time(k++));
    EXPECT_NEAR(rig.command.q_des[2], knee + step, 1e-12) << "frame " << n;
    EXPECT_EQ(rig.err_flag(), kMotorSdkKneeJump) << "frame " << n;
  }
  // no new frame: the held target is still measured against the joint, which has moved 20 deg
  rig.state.q[2] = knee + robot::deg(20.0);
  rig.tick(tick_time(k++));
  EXPECT_NEAR(rig.command.q_des[2], knee + robot::deg(30.0), 1e-12);
  EXPECT_EQ(rig.err_flag(), 0);
  EXPECT_EQ(rig.source.counters().clamped_jumps, 3u);
}

// issue 13: a client stepping 10 deg per frame never jumps 12 deg between adjacent frames, yet
// its target runs away from the joint; the rule measures against the joint, as the firmware does
TEST(MotorSdkSource, JumpIsMeasuredAgainstTheMeasuredAngleNotThePreviousFrame) {
  SourceRig rig;
  rig.enter(0.0);
  int k = rig.activate(1) + 1;
  const double knee = rig.state.q[2];
  JointCommand frame = pose_frame(rig.state.q, 60.0, 2.0);
  for (int n = 1; n <= 5; ++n) {
    frame.q_des[2] = knee + n * robot::deg(10.0);
    rig.push(frame, tick_time(k));
    rig.tick(tick_time(k++));
  }
  EXPECT_NEAR(rig.command.q_des[2], knee + robot::deg(12.0), 1e-12);
  EXPECT_EQ(rig.err_flag(), kMotorSdkKneeJump);
}

TEST(MotorSdkSource, FirstStiffFrameIsMeasuredAgainstTheMeasuredAngle) {
  SourceRig rig;
  rig.enter(0.0);
  int k = rig.activate(1) + 1;
  // after the activation frames (kp 0) the reference is where the joints are
  JointCommand frame = pose_frame(rig.state.q, 20.0, 1.0);
  frame.q_des[1] = rig.state.q[1] - robot::deg(40.0);
  rig.push(frame, tick_time(k));
  rig.tick(tick_time(k));
  EXPECT_NEAR(rig.command.q_des[1], rig.state.q[1] - robot::deg(10.0), 1e-12);
  EXPECT_EQ(rig.err_flag(), kMotorSdkHipJump);
}

TEST(MotorSdkSource, MutationLimitSwitchedOffExecutesTheJump) {
  MotorSdkParameters parameters;
  parameters.position_mutation_limit = false;
  SourceRig rig(parameters);
  rig.enter(0.0);
  int k = rig.activate(1) + 1;
  JointCommand frame = pose_frame(rig.state.q, 20.0, 1.0);
  frame.q_des[2] += robot::deg(30.0);
  rig.push(frame, tick_time(k));
  rig.tick(tick_time(k));
  EXPECT_NEAR(rig.command.q_des[2], rig.state.q[2] + robot::deg(30.0), 1e-12);
  EXPECT_EQ(rig.err_flag(), 0);
  EXPECT_EQ(rig.source.counters().clamped_jumps, 0u);
}

TEST(MotorSdkSource, RangesAreClampedAndCounted) {
  SourceRig rig;
  rig.enter(0.0);
  int k = rig.activate(1) + 1;
  JointCommand frame = pose_frame(rig.state.q, 300.0, 12.0);
  frame.qd_des.fill(-20.0);
  frame.tau_ff.fill(13.0);
  rig.push(frame, tick_time(k));
  rig.tick(tick_time(k));
  EXPECT_EQ(rig.command.kp[0], 200.0);
  EXPECT_EQ(rig.command.kd[0], 10.0);
  EXPECT_EQ(rig.command.qd_des[0], -12.0);
  EXPECT_EQ(rig.command.tau_ff[0], 12.0);
  const MotorSdkCounters counters = rig.source.counters();
  EXPECT_EQ(counters.clamped_gains, 12u);
  EXPECT_EQ(counters.clamped_velocities, 12u);
  EXPECT_EQ(counters.clamped_torques, 12u);
}

TEST(MotorSdkSource, NonFiniteFramesAreRejectedAndCounted) {
  SourceRig rig;
  JointCommand bad;
  bad.tau_ff[4] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(rig.source.mailbox().push(bad, 0.0), PushResult::NonFinite);
  bad.tau_ff[4] = 0.0;
  bad.kp[0] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(rig.source.mailbox().push(bad, 0.0), PushResult::NonFinite);
  EXPECT_FALSE(rig.source.wants_control());  // a bad frame never latches motor mode
  EXPECT_EQ(rig.source.counters().frames_non_finite, 2u);

  // once active, a NaN frame changes nothing: the previous command stays
  rig.enter(0.0);
  int k = rig.activate(1) + 1;
  const JointCommand hold = pose_frame(rig.state.q, 20.0, 1.0);
  rig.push(hold, tick_time(k));
  rig.tick(tick_time(k++));
  JointCommand nan_frame = hold;
  nan_frame.q_des[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(rig.source.mailbox().push(nan_frame, tick_time(k)), PushResult::NonFinite);
  rig.tick(tick_time(k));
  EXPECT_EQ(rig.command.q_des[3], hold.q_des[3]);
  EXPECT_EQ(rig.source.counters().frames_non_finite, 3u);
}

TEST(MotorSdkSource, CtrlTopicIntervalIsTheTimeBetweenTheLastTwoFrames) {
  SourceRig rig;
  rig.enter(0.0);
  rig.push(JointCommand{}, 0.002);
  rig.tick(0.002);
  EXPECT_NEAR(rig.source.status().ctrl_topic_interval_ms, 2.0, 1e-9);
  rig.push(JointCommand{}, 0.008);
  rig.tick(0.008);
  EXPECT_NEAR(rig.source.status().ctrl_topic_interval_ms, 6.0, 1e-9);
}

TEST(MotorSdkSource, RefusedFramesAreDiscardedAndCounted) {
  SourceRig rig;
  rig.push(JointCommand{}, 0.0);
  rig.push(JointCommand{}, 0.002);
  rig.source.on_refused("the shared-memory interface");
  EXPECT_FALSE(rig.source.wants_control());
  EXPECT_EQ(rig.source.counters().frames_refused, 2u);
  EXPECT_STREQ(rig.source.last_refusal_holder(), "the shared-memory interface");
  EXPECT_FALSE(rig.source.status().motor_mode);
}

TEST(MotorSdkSource, FullMailboxDropsAndCounts) {
  SourceRig rig;
  for (std::size_t n = 0; n < MotorSdkMailbox::kCapacity; ++n) {
    EXPECT_EQ(rig.source.mailbox().push(JointCommand{}, 0.0), PushResult::Accepted);
  }
  EXPECT_EQ(rig.source.mailbox().push(JointCommand{}, 0.0), PushResult::Full);
  EXPECT_EQ(rig.source.counters().frames_dropped, 1u);
}

}  // namespace
}  // namespace cerebellum
