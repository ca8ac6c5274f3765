// One source at a time: latching, refusals, and the MC's own behaviour until then.
#include "modes/source_arbiter.hpp"

#include <gtest/gtest.h>

#include <string>

namespace cerebellum {
namespace {

// the MC's own behaviour with a fixed answer on the latch question
class ConstantBehaviour final : public OwnBehaviour {
 public:
  ConstantBehaviour(double kp, bool allows_latch) : kp_(kp), allows_latch_(allows_latch) {}
  void compute(const RobotState&, JointCommand& command) override { command.kp.fill(kp_); }
  ContactPlan contact_plan() const override { return plan; }
  bool allows_low_level_latch() const override { return allows_latch_; }
  ContactPlan plan;
  void on_handover() override { ++handovers; }
  int handovers = 0;

 private:
  double kp_;
  bool allows_latch_;
};

class ScriptedSource final : public LowLevelSource {
 public:
  ScriptedSource(const char* name, double kp) : name_(name), kp_(kp) {}
  const char* name() const override { return name_; }
  bool wants_control() const override { return wants; }
  void on_latched(const RobotState&) override { ++latched; }
  void on_refused(const char* holder) override { last_refusal = holder, ++refused; }
  void compute(const RobotState&, JointCommand& command) override { command.kp.fill(kp_); }

  bool wants = false;
  int latched = 0;
  int refused = 0;
  std::string last_refusal;

 private:
  const char* name_;
  double kp_;
};

TEST(SourceArbiter, OwnBehaviourRunsUntilASourceAsks) {
  ConstantBehaviour own(1.0, true);
  SourceArbiter arbiter(own);
  ScriptedSource sdk("motor_sdk", 2.0);
  arbiter.add_low_level_source(sdk);
  JointCommand command;
  arbiter.compute(RobotState{}, command);
  EXPECT_EQ(command.kp[0], 1.0);
  EXPECT_EQ(arbiter.latched(), nullptr);

  sdk.wants = true;
  arbiter.compute(RobotState{}, command);
  EXPECT_EQ(command.kp[0], 2.0);
  EXPECT_EQ(arbiter.latched(), &sdk);
  EXPECT_EQ(sdk.latched, 1);
  EXPECT_EQ(own.handovers, 1);
  // latched until restart, even when the client goes quiet
  sdk.wants = false;
  arbiter.compute(RobotState{}, command);
  EXPECT_EQ(command.kp[0], 2.0);
}

TEST(SourceArbiter, ContactPlanComesFromWhoeverCommandsTheRobot) {
  ConstantBehaviour own(1.0, true);
  own.plan = ContactSchedule{};
  SourceArbiter arbiter(own);
  ScriptedSource sdk("motor_sdk", 2.0);
  arbiter.add_low_level_source(sdk);
  JointCommand command;
  arbiter.compute(RobotState{}, command);
  EXPECT_TRUE(arbiter.contact_plan().has_value());
  // a low-level source plans no contacts
  sdk.wants = true;
  arbiter.compute(RobotState{}, command);
  EXPECT_EQ(arbiter.latched(), &sdk);
  EXPECT_FALSE(arbiter.contact_plan().has_value());
}

TEST(SourceArbiter, SecondSourceIsRefusedWhileTheFirstHoldsTheRobot) {
  ConstantBehaviour own(1.0, true);
  SourceArbiter arbiter(own);
  ScriptedSource sdk("motor_sdk", 2.0);
  ScriptedSource shm("shm", 3.0);
  arbiter.add_low_level_source(sdk);
  arbiter.add_low_level_source(shm);
  sdk.wants = true;
  shm.wants = true;
  JointCommand command;
  arbiter.compute(RobotState{}, command);
  EXPECT_EQ(command.kp[0], 2.0);
  EXPECT_EQ(shm.refused, 1);
  EXPECT_EQ(shm.last_refusal, "motor_sdk");
  EXPECT_EQ(arbiter.refusals(), 1u);
}

TEST(SourceArbiter, NoLatchWhileTheMcForbidsIt) {
  ConstantBehaviour own(1.0, false);
  SourceArbiter arbiter(own);
  ScriptedSource sdk("motor_sdk", 2.0);
  arbiter.add_low_level_source(sdk);
  sdk.wants = true;
  JointCommand command;
  arbiter.compute(RobotState{}, command);
  EXPECT_EQ(command.kp[0], 1.0);
  EXPECT_EQ(arbiter.latched(), nullptr);
  EXPECT_EQ(sdk.refused, 1);
}

}  // namespace
}  // namespace cerebellum
