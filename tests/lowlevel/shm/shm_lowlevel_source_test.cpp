// The shared-memory source's decisions without shared memory: a fake link hands it command frames
// in the MC's types and records what it publishes and reports. The memory, the flags and the
// vendor structs are tested in tests/io/shm_lowlevel (and the whole MC there, in lockstep).
#include "lowlevel/shm/shm_lowlevel_source.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace cerebellum {
namespace {

class FakeLink final : public ShmLink {
 public:
  bool take_command(JointCommand& command) override {
    calls += "take ";
    if (!flagged) return false;
    command = *flagged;
    flagged.reset();
    return true;
  }
  void publish_state(const SensorFrame& frame) override {
    calls += "publish ";
    published_times.push_back(frame.time_s);
  }
  void report(const ShmEvent& event) override { events.push_back(event); }

  std::optional<JointCommand> flagged;  // the client's frame, taken at the next cycle
  std::string calls;
  std::vector<double> published_times;
  std::vector<ShmEvent> events;
};

// every joint at q_des = index / 10, gains 60 / 2
JointCommand client_frame() {
  JointCommand command;
  for (std::size_t i = 0; i < kNumJoints; ++i) command.q_des[i] = static_cast<double>(i) / 10.0;
  command.kp.fill(60.0);
  command.kd.fill(2.0);
  return command;
}

SensorFrame frame_at(double time_s) {
  SensorFrame frame;
  frame.time_s = time_s;
  for (std::size_t i = 0; i < kNumJoints; ++i) frame.q[i] = -0.01 * static_cast<double>(i);
  return frame;
}

RobotState state_at(double time_s) {
  RobotState state;
  state.time_s = time_s;
  return state;
}

class ShmSource : public ::testing::Test {
 protected:
  static constexpr int kTimeout = 10;

  // one 1 ms cycle, the client's frame (if any) flagged before it; true when the motors got command
  bool cycle(std::optional<JointCommand> frame = std::nullopt) {
    link_.flagged = frame;
    ++cycles_;
    return source_.run_cycle(frame_at(0.001 * cycles_), command_);
  }

  GuardLimits limits_;
  FakeLink link_;
  ShmLowLevelSource source_{link_, kTimeout, limits_};
  JointCommand command_;
  int cycles_ = 0;
};

TEST_F(ShmSource, TakesTheCommandThenPublishesTheStateEveryCycle) {
  EXPECT_FALSE(cycle());
  EXPECT_FALSE(cycle(client_frame()));
  EXPECT_EQ(link_.calls, "take publish take publish ");
  EXPECT_EQ(link_.published_times, (std::vector<double>{0.001, 0.002}));
  EXPECT_EQ(source_.counters().cycles, 2u);
}

TEST_F(ShmSource, BeforeAnyFrameItWantsNothingAndHoldsDamping) {
  EXPECT_FALSE(source_.wants_control());
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    EXPECT_EQ(source_.active_command().kp[i], 0.0);
    EXPECT_EQ(source_.active_command().kd[i], limits_.damping_kd);
  }
  // silence before the first frame is no missed cycle
  for (int k = 0; k < 3 * kTimeout; ++k) cycle();
  EXPECT_EQ(source_.counters().missed_cycles, 0u);
  EXPECT_EQ(source_.counters().command_timeouts, 0u);
  EXPECT_TRUE(link_.events.empty());
}

TEST_F(ShmSource, AValidFrameAsksForControlAndDrivesTheMotorsOnlyOnceLatched) {
  command_.kp.fill(-7.0);  // a marker: an unlatched source does not touch the motors' command
  EXPECT_FALSE(cycle(client_frame()));
  EXPECT_EQ(command_.kp[0], -7.0);
  EXPECT_TRUE(source_.wants_control());
  EXPECT_TRUE(source_.command_active());
  EXPECT_EQ(source_.counters().frames_taken, 1u);

  source_.on_latched(state_at(0.0015));
  EXPECT_TRUE(source_.latched());
  ASSERT_EQ(link_.events.size(), 1u);
  EXPECT_EQ(link_.events[0].kind, ShmEventKind::Latched);
  EXPECT_EQ(link_.events[0].time_s, 0.0015);
  JointCommand tick_command;
  source_.compute(state_at(0.002), tick_command);
  EXPECT_EQ(tick_command.q_des[5], 0.5);

  // the newest frame repeats while the client is silent
  EXPECT_TRUE(cycle());
  EXPECT_EQ(command_.q_des[5], 0.5);
  EXPECT_EQ(command_.kp[0], 60.0);
  EXPECT_EQ(source_.counters().missed_cycles, 1u);
}

TEST_F(ShmSource, SilenceForTheTimeoutDropsTheCommandForDampingAndAFrameResumes) {
  cycle(client_frame());
  source_.on_latched(state_at(0.001));
  for (int missed = 1; missed < kTimeout; ++missed) {
    ASSERT_TRUE(cycle()) << missed;
    EXPECT_TRUE(source_.command_active()) << missed;
    EXPECT_EQ(command_.kp[4], 60.0) << missed;
  }
  EXPECT_TRUE(cycle());
  EXPECT_FALSE(source_.command_active());
  EXPECT_FALSE(source_.wants_control());
  EXPECT_TRUE(source_.latched()) << "the source keeps the robot";
  const SensorFrame now = frame_at(0.001 * cycles_);
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    EXPECT_EQ(command_.kp[i], 0.0) << i;
    EXPECT_EQ(command_.kd[i], limits_.damping_kd) << i;
    EXPECT_EQ(command_.tau_ff[i], 0.0) << i;
    EXPECT_EQ(command_.qd_des[i], 0.0) << i;
    EXPECT_EQ(command_.q_des[i], now.q[i]) << i;
  }
  EXPECT_EQ(source_.counters().command_timeouts, 1u);
  EXPECT_EQ(source_.counters().missed_cycles, static_cast<std::uint64_t>(kTimeout));
  ASSERT_EQ(link_.events.back().kind, ShmEventKind::CommandTimedOut);
  EXPECT_EQ(link_.events.back().missed_cycles, kTimeout);
  EXPECT_EQ(link_.events.back().damping_kd, limits_.damping_kd);
  EXPECT_EQ(link_.events.back().time_s, now.time_s);

  // damping holds through further silence, without more timeouts
  for (int k = 0; k < 3 * kTimeout; ++k) cycle();
  EXPECT_EQ(source_.counters().command_timeouts, 1u);

  EXPECT_TRUE(cycle(client_frame()));
  EXPECT_TRUE(source_.command_active());
  EXPECT_EQ(command_.kp[0], 60.0);
  EXPECT_EQ(link_.events.back().kind, ShmEventKind::CommandResumed);
}

struct BadValue {
  std::size_t joint;
  ShmCommandField field;
  double value;
  ShmCommandFault fault;
};

// the test's name in ctest: readable, and without the struct's padding bytes
void PrintTo(const BadValue& bad, std::ostream* out) {
  *out << "joint " << bad.joint << " " << shm_command_field_name(bad.field) << " = " << bad.value;
}

class ShmSourceRejects : public ShmSource, public ::testing::WithParamInterface<BadValue> {};

TEST_P(ShmSourceRejects, TheWholeFrameKeepsTheLastOneAndReportsTheFirstBadValue) {
  const BadValue bad = GetParam();
  cycle(client_frame());
  const JointCommand good = source_.active_command();
  JointCommand frame = client_frame();
  for (std::size_t i = 0; i < kNumJoints; ++i) frame.q_des[i] = 1.0;  // would move every joint
  switch (bad.field) {
    case ShmCommandField::PDes: frame.q_des[bad.joint] = bad.value; break;
    case ShmCommandField::VDes: frame.qd_des[bad.joint] = bad.value; break;
    case ShmCommandField::Kp: frame.kp[bad.joint] = bad.value; break;
    case ShmCommandField::Kd: frame.kd[bad.joint] = bad.value; break;
    case ShmCommandField::TFf: frame.tau_ff[bad.joint] = bad.value; break;
  }
  cycle(frame);
  for (std::size_t i = 0; i < kNumJoints; ++i) EXPECT_EQ(source_.active_command().q_des[i], good.q_des[i]) << i;
  EXPECT_EQ(source_.counters().frames_rejected, 1u);
  EXPECT_EQ(source_.counters().frames_taken, 1u);
  EXPECT_EQ(source_.counters().missed_cycles, 1u) << "a rejected frame counts as a missing one";
  ASSERT_EQ(link_.events.size(), 1u);
  const ShmEvent& event = link_.events[0];
  EXPECT_EQ(event.kind, ShmEventKind::FrameRejected);
  EXPECT_EQ(event.time_s, 0.002);
  EXPECT_EQ(event.check.fault, bad.fault);
  EXPECT_EQ(event.check.joint, bad.joint);
  EXPECT_EQ(event.check.field, bad.field);
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

INSTANTIATE_TEST_SUITE_P(BadFrames, ShmSourceRejects,
                         ::testing::Values(BadValue{4, ShmCommandField::PDes, kNaN, ShmCommandFault::NonFinite},
                                           BadValue{0, ShmCommandField::VDes, -kInf, ShmCommandFault::NonFinite},
                                           BadValue{8, ShmCommandField::Kp, kInf, ShmCommandFault::NonFinite},
                                           BadValue{11, ShmCommandField::Kd, kNaN, ShmCommandFault::NonFinite},
                                           BadValue{9, ShmCommandField::TFf, kInf, ShmCommandFault::NonFinite},
                                           BadValue{5, ShmCommandField::Kp, -1.0, ShmCommandFault::GainOutOfRange},
                                           BadValue{5, ShmCommandField::Kp, 200.5, ShmCommandFault::GainOutOfRange},
                                           BadValue{1, ShmCommandField::Kp, 1e6, ShmCommandFault::GainOutOfRange},
                                           BadValue{7, ShmCommandField::Kd, -0.1, ShmCommandFault::GainOutOfRange},
                                           BadValue{6, ShmCommandField::Kd, 10.5, ShmCommandFault::GainOutOfRange}));

TEST_F(ShmSource, GainsOnTheBoundsAreTaken) {
  JointCommand frame = client_frame();
  frame.kp[0] = limits_.command.kp_max;
  frame.kd[0] = limits_.command.kd_max;
  frame.kp[11] = 0.0;
  frame.kd[11] = 0.0;
  cycle(frame);
  EXPECT_EQ(source_.counters().frames_rejected, 0u);
  EXPECT_EQ(source_.active_command().kp[0], limits_.command.kp_max);
  EXPECT_EQ(source_.active_command().kd[0], limits_.command.kd_max);
}

TEST_F(ShmSource, OnlyRejectedFramesForTheTimeoutDropTheCommand) {
  cycle(client_frame());
  JointCommand bad = client_frame();
  bad.kd[3] = kNaN;
  for (int k = 1; k < kTimeout; ++k) cycle(bad);
  EXPECT_TRUE(source_.command_active());
  cycle(bad);
  EXPECT_FALSE(source_.command_active());
  EXPECT_EQ(source_.active_command().kp[0], 0.0);
}

TEST_F(ShmSource, ARefusedStretchIsCountedEveryTickAndReportedOnce) {
  cycle(client_frame());
  for (int k = 0; k < 5; ++k) {
    source_.on_refused("another source");
    cycle(client_frame());
  }
  EXPECT_EQ(source_.counters().refusals, 5u);
  ASSERT_EQ(link_.events.size(), 1u);
  EXPECT_EQ(link_.events[0].kind, ShmEventKind::Refused);
  EXPECT_STREQ(link_.events[0].holder, "another source");
  EXPECT_EQ(link_.events[0].time_s, 0.001) << "the robot time of the newest cycle";
  EXPECT_FALSE(source_.latched());

  // a timeout ends the stretch: the next refused one is reported again
  for (int k = 0; k < kTimeout; ++k) cycle();
  cycle(client_frame());
  source_.on_refused("another source");
  EXPECT_EQ(link_.events.back().kind, ShmEventKind::Refused);
  EXPECT_EQ(source_.counters().refusals, 6u);
}

TEST(ShmSourceConfiguration, ATimeoutBelowOneCycleIsRefused) {
  FakeLink link;
  EXPECT_THROW(ShmLowLevelSource(link, 0, GuardLimits{}), std::invalid_argument);
  EXPECT_NO_THROW(ShmLowLevelSource(link, 1, GuardLimits{}));
}

}  // namespace
}  // namespace cerebellum
