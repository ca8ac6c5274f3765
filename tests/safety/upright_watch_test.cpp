// When the two-leg stand gives up: beyond either limit, or on a state that is not a number.
#include "safety/upright_watch.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace cerebellum {
namespace {

TEST(UprightWatch, ABalanceWithinBothLimitsIsKept) {
  EXPECT_FALSE(upright_balance_lost(0.59, 0.11));
  EXPECT_FALSE(upright_balance_lost(0.0, 0.0));
}

TEST(UprightWatch, TiltOrOffsetAtTheirLimitsIsLost) {
  const UprightWatchLimits limits;
  EXPECT_TRUE(upright_balance_lost(limits.tilt_error_rad, 0.0));
  EXPECT_TRUE(upright_balance_lost(0.0, limits.offset_error_m));
}

TEST(UprightWatch, AStateThatIsNotANumberIsLost) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(upright_balance_lost(nan, 0.0));
  EXPECT_TRUE(upright_balance_lost(0.0, nan));
}

}  // namespace
}  // namespace cerebellum
