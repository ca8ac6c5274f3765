// The one finiteness check of a joint command: every field of every joint counts.
#include "safety/command_finite.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace cerebellum {
namespace {

TEST(CommandFinite, AnyNonFiniteFieldMakesTheCommandNonFinite) {
  const double bad[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                        -std::numeric_limits<double>::infinity()};
  for (double value : bad) {
    for (int field = 0; field < 5; ++field) {
      for (std::size_t joint : {std::size_t{0}, std::size_t{11}}) {
        JointCommand command;
        JointArray<double>* arrays[] = {&command.q_des, &command.qd_des, &command.kp, &command.kd, &command.tau_ff};
        (*arrays[field])[joint] = value;
        EXPECT_FALSE(command_is_finite(command)) << "field " << field;
        // the field is named by its position in JointCommand
        EXPECT_EQ(non_finite_field(command, joint), static_cast<CommandField>(field));
        EXPECT_FALSE(non_finite_field(command, 5));
      }
    }
  }
  EXPECT_TRUE(command_is_finite(JointCommand{}));
}

TEST(CommandFinite, NamesTheFirstBadFieldOfAJoint) {
  JointCommand command;
  command.kd[3] = std::numeric_limits<double>::quiet_NaN();
  command.tau_ff[3] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(non_finite_field(command, 3), CommandField::Kd);
}

TEST(CommandFinite, ReadsEachFieldFromItsArray) {
  JointCommand command;
  command.q_des[4] = 1.0;
  command.qd_des[4] = 2.0;
  command.kp[4] = 3.0;
  command.kd[4] = 4.0;
  command.tau_ff[4] = 5.0;
  EXPECT_EQ(command_value(command, 4, CommandField::QDes), 1.0);
  EXPECT_EQ(command_value(command, 4, CommandField::QdDes), 2.0);
  EXPECT_EQ(command_value(command, 4, CommandField::Kp), 3.0);
  EXPECT_EQ(command_value(command, 4, CommandField::Kd), 4.0);
  EXPECT_EQ(command_value(command, 4, CommandField::TauFf), 5.0);
}

}  // namespace
}  // namespace cerebellum
