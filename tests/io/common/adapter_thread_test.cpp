#include "io/common/adapter_thread.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

namespace cerebellum {
namespace {

TEST(AdapterThread, RepeatsItsStepUntilStoppedThenDrainsOnce) {
  std::atomic<int> steps{0};
  std::atomic<int> drains{0};
  int steps_at_drain = -1;
  {
    AdapterThread thread;
    thread.start([&] { ++steps; },
                 [&] {
                   steps_at_drain = steps.load();
                   ++drains;
                 });
    while (steps.load() < 3) std::this_thread::yield();
    thread.stop();
    EXPECT_FALSE(thread.running());
    thread.stop();  // twice is harmless
  }
  EXPECT_EQ(drains.load(), 1);
  EXPECT_EQ(steps_at_drain, steps.load());
}

TEST(AdapterThread, TheDestructorStopsARunningThread) {
  std::atomic<int> steps{0};
  {
    AdapterThread thread;
    thread.start([&] { ++steps; });
    while (steps.load() == 0) std::this_thread::yield();
  }
  const int after = steps.load();
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_EQ(steps.load(), after);
}

}  // namespace
}  // namespace cerebellum
