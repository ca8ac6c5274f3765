// The MC on the simulated robot in lockstep, with the ground-truth publisher and a subscriber in the
// same private network namespace: the rate is in simulated time, and the messages are the
// simulation's truth (a standing robot at rest: its height, level trunk, four feet down).
#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "loop/mc.hpp"
#include "loop/simulated_robot.hpp"
#include "io/lcm_sim_truth/sim_truth_publisher.hpp"
#include "sim_truth_lcmt.hpp"

namespace cerebellum {
namespace {

class Subscriber {
 public:
  explicit Subscriber(const std::string& url) : lcm_(url) {
    lcm_.subscribe(kSimTruthChannel, &Subscriber::on_message, this);
  }
  void drain() {
    while (lcm_.handleTimeout(200) > 0) {
    }
  }
  const std::vector<sim_truth_lcmt>& messages() const { return messages_; }

 private:
  void on_message(const lcm::ReceiveBuffer*, const std::string&, const sim_truth_lcmt* message) {
    messages_.push_back(*message);
  }
  lcm::LCM lcm_;
  std::vector<sim_truth_lcmt> messages_;
};

struct TruthRun {
  std::vector<sim_truth_lcmt> messages;
  GroundTruth final_truth;
};

TruthRun run_standing(double rate_hz, double seconds) {
  McConfig config = default_config();
  config.startup = Startup::Stand;  // the MC stands the robot up by itself
  config.sim_truth.rate_hz = rate_hz;
  Mc mc = make_simulated_mc(config);
  Subscriber subscriber(config.highlevel.odometry_url);
  SimTruthPublisher publisher(mc.simulation(), config.highlevel.odometry_url, config.sim_truth, config.loop_period_s);
  mc.loop().add_observer(publisher);
  const int ticks = static_cast<int>(std::lround(seconds / config.loop_period_s));
  for (int i = 0; i < ticks; ++i) {
    mc.loop().tick();
    // a 64-sample ring between the loop and the publisher: let it keep up
    if (i % 100 == 99) subscriber.drain();
  }
  publisher.finish();
  subscriber.drain();
  EXPECT_EQ(publisher.dropped(), 0u);
  return TruthRun{subscriber.messages(), mc.simulation().ground_truth()};
}

TEST(SimTruthPublisher, PublishesAtTheConfiguredRateOfSimulatedTime) {
  for (const double rate_hz : {50.0, 125.0}) {
    const TruthRun run = run_standing(rate_hz, 1.0);
    ASSERT_EQ(run.messages.size(), static_cast<std::size_t>(std::lround(rate_hz))) << rate_hz << " Hz";
    for (std::size_t k = 1; k < run.messages.size(); ++k) {
      EXPECT_EQ(run.messages[k].timestamp - run.messages[k - 1].timestamp, std::llround(1e9 / rate_hz));
    }
  }
}

TEST(SimTruthPublisher, ShowsTheRobotStandingAtRestAsTheSimulationHasIt) {
  const TruthRun run = run_standing(50.0, 4.0);
  ASSERT_FALSE(run.messages.empty());
  const sim_truth_lcmt& last = run.messages.back();
  // the last message is 20 ms older than the final truth: at rest, the same state
  EXPECT_NEAR(last.position[2], run.final_truth.position[2], 1e-3);
  EXPECT_GT(last.position[2], 0.2);
  double norm = 0.0;
  for (double c : last.quaternion) norm += c * c;
  EXPECT_NEAR(norm, 1.0, 1e-9);
  EXPECT_GT(std::abs(last.quaternion[0]), std::cos(0.05 / 2));
  for (int leg = 0; leg < 4; ++leg) EXPECT_TRUE(last.foot_contact[leg]) << leg;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    EXPECT_NEAR(last.q[i], run.final_truth.q[i], 2e-3) << i;
    EXPECT_NEAR(last.tau[i], run.final_truth.tau[i], 0.5) << i;
  }
  // earlier messages saw the robot dropped from 0.3 m, lying, then rising
  double lowest_m = last.position[2];
  for (const sim_truth_lcmt& message : run.messages) lowest_m = std::min(lowest_m, message.position[2]);
  EXPECT_EQ(run.messages.front().position[2], 0.3);
  EXPECT_LT(lowest_m, last.position[2] - 0.1);
}

TEST(SimTruthPublisher, RefusesARateOutsideItsRange) {
  McConfig config = default_config();
  Mc mc = make_simulated_mc(config);
  for (const double rate_hz : {0.0, -5.0, 501.0, std::nan("")}) {
    config.sim_truth.rate_hz = rate_hz;
    EXPECT_THROW(SimTruthPublisher(mc.simulation(), config.highlevel.odometry_url, config.sim_truth, 0.002),
                 std::invalid_argument)
        << rate_hz;
  }
}

}  // namespace
}  // namespace cerebellum
