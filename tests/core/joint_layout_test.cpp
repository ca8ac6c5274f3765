#include "core/joint_layout.hpp"

#include <gtest/gtest.h>

#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

TEST(JointLayout, FlatIndexIsThreePerLegInFrFlRrRlOrder) {
  EXPECT_EQ(joint_index(Leg::FR, Joint::Abad), 0u);
  EXPECT_EQ(joint_index(Leg::FL, Joint::Hip), 4u);
  EXPECT_EQ(joint_index(Leg::RR, Joint::Knee), 8u);
  EXPECT_EQ(joint_index(Leg::RL, Joint::Knee), 11u);
}

TEST(JointLayout, WireConventionNegatesHipAndKneeOnly) {
  JointArray<double> sdk{};
  for (std::size_t i = 0; i < kNumJoints; ++i) sdk[i] = 1.0 + static_cast<double>(i);
  const JointArray<double> wire = sdk_to_wire(sdk);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    EXPECT_EQ(wire[3 * leg + 0], sdk[3 * leg + 0]);
    EXPECT_EQ(wire[3 * leg + 1], -sdk[3 * leg + 1]);
    EXPECT_EQ(wire[3 * leg + 2], -sdk[3 * leg + 2]);
  }
  EXPECT_EQ(wire_to_sdk(wire), sdk);
}

TEST(JointLayout, RangesAreTheReferenceFigures) {
  EXPECT_EQ(robot::joint_range(0).lower, -0.68);
  EXPECT_EQ(robot::joint_range(1).upper, 2.79);
  EXPECT_EQ(robot::joint_range(7).lower, -0.98);
  EXPECT_EQ(robot::joint_range(10).upper, 3.14);
  EXPECT_EQ(robot::joint_range(11).lower, -2.53);
  EXPECT_EQ(robot::joint_range(11).upper, -0.52);
}

}  // namespace
}  // namespace cerebellum
