// The slow link around a robot: each command reaches the robot the given number of ticks after it
// was written, and each state reaches the MC the given number of ticks after it was measured,
// checked tick by tick against a robot that stamps its states and records its commands.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "backend/latent_link_backend.hpp"

namespace cerebellum {
namespace {

// a robot whose n-th state (from 1) says n in time_s, and which records the commands it is given
class StampingRobot final : public RobotBackend {
 public:
  explicit StampingRobot(std::vector<double>& given) : given_(given) {}
  SensorFrame read() override {
    SensorFrame frame;
    frame.time_s = ++reads_;
    return frame;
  }
  void write(const JointCommand& command) override { given_.push_back(command.tau_ff[0]); }
  void advance(double) override {}
  double time_s() const override { return reads_; }

 private:
  std::vector<double>& given_;
  int reads_ = 0;
};

struct Ticks {
  std::vector<double> states_seen;  // the stamp the MC read at each tick
  std::vector<double> given;        // the commands the robot was given, in order
};

// `ticks` ticks of read, write (command k says k), advance
Ticks run(LinkLatencyTicks latency, int ticks) {
  Ticks out;
  LatentLinkBackend link(std::make_unique<StampingRobot>(out.given), latency);
  for (int k = 1; k <= ticks; ++k) {
    out.states_seen.push_back(link.read().time_s);
    JointCommand command;
    command.tau_ff[0] = k;
    link.write(command);
    link.advance(0.002);
  }
  return out;
}

TEST(LatentLinkBackend, WithoutLatencyPassesEveryStateAndCommandAtOnce) {
  const Ticks t = run({0, 0}, 5);
  EXPECT_EQ(t.states_seen, (std::vector<double>{1, 2, 3, 4, 5}));
  EXPECT_EQ(t.given, (std::vector<double>{1, 2, 3, 4, 5}));
}

TEST(LatentLinkBackend, TheMcReadsEachStateTheGivenTicksAfterItWasMeasured) {
  for (int state_ticks : {1, 2, 5}) {
    const Ticks t = run({0, state_ticks}, 12);
    for (int k = 1; k <= 12; ++k) {
      // until state_ticks + 1 states exist the first one is all there is
      const double expected = k - state_ticks >= 1 ? k - state_ticks : 1;
      EXPECT_EQ(t.states_seen[static_cast<std::size_t>(k - 1)], expected) << state_ticks << " ticks, tick " << k;
    }
  }
}

TEST(LatentLinkBackend, TheRobotGetsEachCommandTheGivenTicksAfterItWasWritten) {
  for (int command_ticks : {1, 3, 4}) {
    const Ticks t = run({command_ticks, 0}, 12);
    // nothing reaches the robot in the first command_ticks ticks; then commands 1, 2, ... in order
    ASSERT_EQ(t.given.size(), static_cast<std::size_t>(12 - command_ticks)) << command_ticks;
    for (std::size_t i = 0; i < t.given.size(); ++i) EXPECT_EQ(t.given[i], static_cast<double>(i + 1));
  }
}

TEST(LatentLinkBackend, BothWaysAtOnceAddUp) {
  const Ticks t = run({2, 3}, 10);
  EXPECT_EQ(t.states_seen[9], 7.0);
  ASSERT_EQ(t.given.size(), 8u);
  EXPECT_EQ(t.given.back(), 8.0);
}

TEST(LatentLinkBackend, RefusesANegativeLatency) {
  std::vector<double> given;
  EXPECT_THROW(LatentLinkBackend(std::make_unique<StampingRobot>(given), LinkLatencyTicks{-1, 0}),
               std::invalid_argument);
}

}  // namespace
}  // namespace cerebellum
