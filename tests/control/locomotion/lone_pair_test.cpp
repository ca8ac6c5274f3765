// Which pair stands alone, over all sixteen contact sets of four legs.
#include "control/locomotion/lone_pair.hpp"

#include <gtest/gtest.h>

namespace cerebellum {
namespace {

TEST(LonePair, IsTheFrontOrTheRearPairStandingWithNoOtherFootDown) {
  int front = 0;
  int rear = 0;
  for (int bits = 0; bits < 16; ++bits) {
    // bit i: leg i (FR, FL, RR, RL) stands
    const std::array<bool, kNumLegs> stance{(bits & 1) != 0, (bits & 2) != 0, (bits & 4) != 0, (bits & 8) != 0};
    const LonePair expected = bits == 0b0011 ? LonePair::Front : bits == 0b1100 ? LonePair::Rear : LonePair::None;
    EXPECT_EQ(lone_pair(stance), expected) << bits;
    front += lone_pair(stance) == LonePair::Front;
    rear += lone_pair(stance) == LonePair::Rear;
  }
  EXPECT_EQ(front, 1);
  EXPECT_EQ(rear, 1);
}

}  // namespace
}  // namespace cerebellum
