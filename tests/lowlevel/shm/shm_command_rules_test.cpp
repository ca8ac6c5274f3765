// The shared-memory command rules on JointCommand values: the first offending value in joint
// order, NaN/Inf before the gains of the same joint, bounds inclusive.
#include "lowlevel/shm/shm_command_rules.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace cerebellum {
namespace {

JointCommand valid_command() {
  JointCommand command;
  command.kp.fill(60.0);
  command.kd.fill(2.0);
  return command;
}

TEST(ShmCommandRules, AValidCommandPasses) { EXPECT_TRUE(check_shm_command(valid_command(), CommandLimits{}).ok()); }

TEST(ShmCommandRules, GainsOnTheBoundsPassAndJustBeyondThemAreRejected) {
  const CommandLimits limits;
  JointCommand command = valid_command();
  command.kp[4] = limits.kp_max;
  command.kd[4] = limits.kd_max;
  command.kp[5] = 0.0;
  command.kd[5] = 0.0;
  EXPECT_TRUE(check_shm_command(command, limits).ok());
  command.kd[7] = std::nextafter(limits.kd_max, 1e9);
  const ShmCommandCheck check = check_shm_command(command, limits);
  EXPECT_EQ(check.fault, ShmCommandFault::GainOutOfRange);
  EXPECT_EQ(check.joint, 7u);
  EXPECT_EQ(check.field, ShmCommandField::Kd);
  EXPECT_EQ(check.value, command.kd[7]);
}

TEST(ShmCommandRules, ReportsTheFirstBadValueInJointOrder) {
  // a gain out of range on joint 2 comes before a NaN on joint 9; on joint 2 itself a NaN comes
  // before the gain
  JointCommand command = valid_command();
  command.kp[2] = -1.0;
  command.tau_ff[9] = std::numeric_limits<double>::quiet_NaN();
  ShmCommandCheck check = check_shm_command(command, CommandLimits{});
  EXPECT_EQ(check.fault, ShmCommandFault::GainOutOfRange);
  EXPECT_EQ(check.joint, 2u);
  command.qd_des[2] = std::numeric_limits<double>::infinity();
  check = check_shm_command(command, CommandLimits{});
  EXPECT_EQ(check.fault, ShmCommandFault::NonFinite);
  EXPECT_EQ(check.joint, 2u);
  EXPECT_EQ(check.field, ShmCommandField::VDes);
  EXPECT_TRUE(std::isinf(check.value));
}

TEST(ShmCommandRules, FieldsAreNamedAsInLowlevelH) {
  EXPECT_STREQ(shm_command_field_name(ShmCommandField::PDes), "p_des");
  EXPECT_STREQ(shm_command_field_name(ShmCommandField::VDes), "v_des");
  EXPECT_STREQ(shm_command_field_name(ShmCommandField::Kp), "kp");
  EXPECT_STREQ(shm_command_field_name(ShmCommandField::Kd), "kd");
  EXPECT_STREQ(shm_command_field_name(ShmCommandField::TFf), "t_ff");
}

}  // namespace
}  // namespace cerebellum
