// The receiver's listening window: a gap between its steps longer than the pause starts it again.
#include "io/robot_link/listening_window.hpp"

#include <gtest/gtest.h>

namespace cerebellum {
namespace {

TEST(ListeningClock, AGapBetweenStepsLongerThanThePauseStartsTheWindowAgain) {
  ListeningClock receiver(0.005);
  receiver.step(1.000);
  receiver.step(1.004);
  EXPECT_DOUBLE_EQ(receiver.window().since_s, 1.000) << "4 ms between steps: still listening";
  EXPECT_DOUBLE_EQ(receiver.window().until_s, 1.004);
  receiver.step(1.010);
  EXPECT_DOUBLE_EQ(receiver.window().since_s, 1.010) << "6 ms between steps: a pause of its own";
  EXPECT_DOUBLE_EQ(receiver.window().until_s, 1.010);
}

}  // namespace
}  // namespace cerebellum
