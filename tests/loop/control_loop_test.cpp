// The control loop's cycle with a fake robot: stage order, guard, substeps, durations, and the
// contact plan carried from the control stage to the estimator.
#include "loop/control_loop.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <future>
#include <thread>

#include "backend/fake_backend.hpp"
#include "estimation/kinematic_estimator.hpp"

namespace cerebellum {
namespace {

// commands every joint to a fixed target and remembers the states it saw
class RecordingController final : public MotionController {
 public:
  void compute(const RobotState& state, JointCommand& command) override {
    seen_times.push_back(state.time_s);
    command = JointCommand{};
    command.q_des.fill(target);
    command.kp.fill(30.0);
    command.kd.fill(1.0);
  }
  double target = 0.2;
  std::vector<double> seen_times;
};

class CountingObserver final : public CycleObserver {
 public:
  void on_cycle(const CycleRecord& record) override { last_tick = record.tick, ++calls; }
  std::uint64_t last_tick = 0;
  int calls = 0;
};

struct Loop {
  explicit Loop(MotionController& controller, double period_s = 0.002)
      : loop(backend, estimator, controller, GuardLimits{}, period_s) {}
  FakeBackend backend;
  KinematicEstimator estimator;
  ControlLoop loop;
};

TEST(ControlLoop, EachTickReadsOnceControlsWritesAndAdvancesOnePeriod) {
  RecordingController controller;
  Loop l(controller);
  CountingObserver observer;
  l.loop.add_observer(observer);
  for (int i = 0; i < 5; ++i) l.loop.tick();
  EXPECT_EQ(l.backend.read_count(), 5);
  ASSERT_EQ(l.backend.written().size(), 5u);
  EXPECT_NEAR(l.backend.time_s(), 0.010, 1e-12);
  EXPECT_EQ(controller.seen_times, (std::vector<double>{0.0, 0.002, 0.004, 0.006, 0.008}));
  EXPECT_EQ(observer.calls, 5);
  EXPECT_EQ(observer.last_tick, 4u);
  EXPECT_DOUBLE_EQ(l.backend.written().back().q_des[0], 0.2);
}

TEST(ControlLoop, GuardClampsTheControllersCommandIntoJointLimits) {
  RecordingController controller;
  controller.target = 5.0;  // beyond every joint's range
  Loop l(controller);
  const CycleRecord& record = l.loop.tick();
  EXPECT_TRUE(record.safety.flags & kGuardClampedPosition);
  EXPECT_DOUBLE_EQ(l.backend.written()[0].q_des[0], 0.68 - 0.04);
  EXPECT_DOUBLE_EQ(l.backend.written()[0].q_des[2], -0.52 - 0.04);
}

TEST(ControlLoop, NonFiniteSensorDataGivesDampingWithoutAskingTheController) {
  RecordingController controller;
  Loop l(controller);
  l.backend.frame().imu_gyro[1] = std::nan("");
  const CycleRecord& record = l.loop.tick();
  EXPECT_TRUE(record.safety.flags & kGuardInvalidState);
  EXPECT_TRUE(controller.seen_times.empty());
  const JointCommand& written = l.backend.written()[0];
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    EXPECT_EQ(written.kp[i], 0.0);
    EXPECT_EQ(written.kd[i], GuardLimits{}.damping_kd);
  }
}

TEST(ControlLoop, SubstepParticipantsRunEveryMillisecondAndTheirCommandsAreGuarded) {
  class Participant final : public SubstepParticipant {
   public:
    bool on_substep(const SensorFrame& frame, JointCommand& command) override {
      times.push_back(frame.time_s);
      command.kp.fill(1000.0);  // beyond kp_max: the guard must clamp
      return true;
    }
    std::vector<double> times;
  } participant;
  RecordingController controller;
  Loop l(controller);
  l.loop.add_substep_participant(participant);
  l.loop.tick();
  l.loop.tick();
  ASSERT_EQ(participant.times.size(), 4u);
  EXPECT_NEAR(participant.times[1], 0.001, 1e-12);
  EXPECT_NEAR(participant.times[3], 0.003, 1e-12);
  ASSERT_EQ(l.backend.written().size(), 6u);  // per tick: control write + two substep writes
  EXPECT_DOUBLE_EQ(l.backend.written().back().kp[0], GuardLimits{}.command.kp_max);
}

TEST(ControlLoop, TheSubstepGuardsReportIsKeptInTheCycleRecord) {
  // the participant sends an out-of-range kp on the first substep and a NaN on the second of
  // the first tick only
  class Participant final : public SubstepParticipant {
   public:
    bool on_substep(const SensorFrame&, JointCommand& command) override {
      ++calls;
      if (calls == 1) command.kp.fill(1000.0);
      if (calls == 2) command.tau_ff[3] = std::nan("");
      return calls <= 2;
    }
    int calls = 0;
  } participant;
  RecordingController controller;
  Loop l(controller);
  l.loop.add_substep_participant(participant);
  const CycleRecord& first = l.loop.tick();
  // the substeps start from the guarded command: only what the participant did is flagged
  EXPECT_EQ(first.substep_safety.flags, kGuardClampedGain | kGuardNonFiniteCommand);
  EXPECT_TRUE(first.substep_safety.replaced());
  const CycleRecord& second = l.loop.tick();
  EXPECT_EQ(second.substep_safety.flags, kGuardOk);
}

TEST(ControlLoop, RunStopsAfterTheDurationInRobotTime) {
  RecordingController controller;
  Loop l(controller);
  const std::atomic<bool> stop{false};
  const RunStats stats = l.loop.run({0.5, 0.0}, stop);
  EXPECT_EQ(stats.ticks, 250u);
  EXPECT_NEAR(stats.robot_time_s, 0.5, 1e-9);
}

TEST(ControlLoop, RunReturnsAtOnceWhenStopIsSet) {
  RecordingController controller;
  Loop l(controller);
  const std::atomic<bool> stop{true};
  EXPECT_EQ(l.loop.run({-1.0, 0.0}, stop).ticks, 0u);
}

// stops the run from inside its first tick, the way a signal arrives while the loop waits
class StoppingController final : public MotionController {
 public:
  explicit StoppingController(std::atomic<bool>& stop) : stop_(stop) {}
  void compute(const RobotState&, JointCommand& command) override {
    command = JointCommand{};
    stop_.store(true);
  }

 private:
  std::atomic<bool>& stop_;
};

TEST(ControlLoop, AStopEndsTheRunAtOnceEvenWhenThePaceWaitsMinutesPerSubstep) {
  std::atomic<bool> stop{false};
  StoppingController controller(stop);
  Loop l(controller);
  // 1e-6 of real time: each 0.5 ms substep is paced to 500 s of wall time; the run must not
  // wait them out once stopped (the generous limit below is 15 of those waits shorter)
  std::future<RunStats> run = std::async(std::launch::async, [&] { return l.loop.run({-1.0, 1e-6}, stop); });
  ASSERT_EQ(run.wait_for(std::chrono::seconds(30)), std::future_status::ready) << "the run did not stop";
  EXPECT_EQ(run.get().ticks, 1u);
}

// stands for a host that stops the loop once: its tick at 20 ms takes 40 ms of wall time
class StallingController final : public MotionController {
 public:
  void compute(const RobotState& state, JointCommand& command) override {
    command = JointCommand{};
    if (!stalled && state.time_s >= 0.02) {
      stalled = true;
      std::this_thread::sleep_for(std::chrono::milliseconds(40));
    }
  }
  bool stalled = false;
};

TEST(ControlLoop, APacedLoopTheHostStoppedResumesFromThereInsteadOfRunningTheLostTimeInABurst) {
  StallingController controller;
  Loop l(controller);
  const std::atomic<bool> stop{false};
  const RunStats stats = l.loop.run({0.1, 1.0}, stop);
  EXPECT_EQ(stats.ticks, 50u);
  EXPECT_GE(stats.pace_slips, 1u);
  EXPECT_GE(stats.slipped_wall_s, 0.035);
  // caught up, 0.1 s of robot time would end 0.1 s after the start; resumed, the 40 ms stop is
  // added (a lower bound: a slower host only adds to it)
  EXPECT_GE(stats.wall_time_s, stats.robot_time_s + 0.035);
}

// plans every leg in stance with the tick count as its stance phase (none on the first tick)
class PlanningController final : public MotionController {
 public:
  void compute(const RobotState&, JointCommand& command) override {
    command = JointCommand{};
    ++computed;
  }
  ContactPlan contact_plan() const override {
    if (computed < 2) return std::nullopt;
    ContactSchedule schedule{};
    for (LegContactPlan& leg : schedule) leg = {1.0, static_cast<double>(computed)};
    return schedule;
  }
  int computed = 0;
};

// the kinematic estimate, remembering the plans it was handed
class PlanRecordingEstimator final : public StateEstimator {
 public:
  void reset() override { inner.reset(); }
  void update(const SensorFrame& frame, const ContactPlan& plan, RobotState& state) override {
    plans.push_back(plan ? (*plan)[0].stance_phase : -1.0);
    inner.update(frame, plan, state);
  }
  KinematicEstimator inner;
  std::vector<double> plans;  // stance phase of leg 0, -1 for no plan
};

TEST(ControlLoop, TheControllersContactPlanReachesTheEstimatorAtTheNextTick) {
  PlanningController controller;
  FakeBackend backend;
  PlanRecordingEstimator estimator;
  ControlLoop loop(backend, estimator, controller, GuardLimits{}, 0.002);
  for (int i = 0; i < 4; ++i) loop.tick();
  // tick 0 has no plan yet; the first compute plans none; then each tick sees the plan of the one before
  EXPECT_EQ(estimator.plans, (std::vector<double>{-1.0, -1.0, 2.0, 3.0}));
  ASSERT_TRUE(loop.last_cycle().contact_plan.has_value());
  EXPECT_EQ((*loop.last_cycle().contact_plan)[3].stance_phase, 4.0);
}

TEST(ControlLoop, RejectsAPeriodTheSubstepDoesNotDivide) {
  RecordingController controller;
  FakeBackend backend;
  KinematicEstimator estimator;
  EXPECT_THROW(ControlLoop(backend, estimator, controller, GuardLimits{}, 0.0025, 0.001), std::invalid_argument);
  EXPECT_THROW(ControlLoop(backend, estimator, controller, GuardLimits{}, 0.0, 0.001), std::invalid_argument);
}

}  // namespace
}  // namespace cerebellum
