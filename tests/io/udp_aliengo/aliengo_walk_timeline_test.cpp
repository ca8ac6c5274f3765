// The AlienGo SDK's walk example timeline (docs/aliengo-udp.md), streamed tick by tick through the
// sport session into the MC in lockstep; every stage judged on the simulator's truth. A minute of
// lockstep simulation (label long): the sanitized CI stage leaves it out, the Release stage runs it.
#include <gtest/gtest.h>

#include <cmath>

#include "io/udp_aliengo/aliengo_sim.hpp"
#include "modes/command_ranges.hpp"

namespace cerebellum {
namespace {

using testing::AlienGoSim;

// the vendor example's command at time t (ms), as examples/aliengo/aliengo_walk.cpp sends it
AlienGoCommand walk_timeline(int t) {
  AlienGoCommand c;
  const auto in = [t](int from, int to) { return t >= from && t < to; };
  if (in(1000, 2000)) {
    c.mode = 1;
    c.rpy[0] = 0.7f;
  } else if (in(2000, 3000)) {
    c.mode = 1;
  } else if (in(3000, 4000)) {
    c.mode = 1;
    c.rpy[1] = 0.4f;
  } else if (in(5000, 6000)) {
    c.mode = 1;
    c.rpy[2] = 0.5f;
  } else if (in(8000, 9000)) {
    c.mode = 1;
    c.body_height_m = 0.05f;
  } else if (in(9000, 10000)) {
    c.mode = 1;
    c.body_height_m = -0.15f;
  } else if (in(11000, 13000)) {
    c.mode = 2;
    c.velocity = {0.2f, 0.0f};
    c.yaw_speed = 0.3f;
  } else if (in(13000, 15000)) {
    c.mode = 2;
    c.velocity = {-0.2f, 0.0f};
    c.yaw_speed = -0.1f;
    c.foot_raise_m = 0.1f;
  } else if (in(17000, 23000)) {
    c.mode = 3;
    c.position = {1.0f, 0.0f};
    c.body_height_m = -0.05f;
  } else if (in(25000, 32000)) {
    c.mode = 2;
    c.gait_type = 2;
    c.velocity = {0.1f, 0.0f};
  } else if (in(32000, 40000)) {
    c.mode = 2;
    c.gait_type = 2;
    c.velocity = {-0.1f, 0.0f};
  } else if (in(40000, 42000)) {
    c.mode = 1;
  } else if (in(42000, 44000) || in(46000, 48000) || in(51000, 53000)) {
    c.mode = 5;
  } else if (in(44000, 46000) || in(53000, 55000)) {
    c.mode = 6;
  } else if (in(48000, 51000)) {
    c.mode = 7;
  } else if (in(55000, 57000)) {
    c.mode = 1;
  } else if (in(57000, 65000)) {
    c.mode = 3;
  }
  return c;
}

class AlienGoWalkTimeline : public ::testing::Test {
 protected:
  void SetUp() override {
    sim.idle(3.0);  // the MC stands up by itself
    start_s = sim.time_s();
    origin = sim.true_xy();
    origin_yaw = sim.true_rpy().z();
  }
  // streams the timeline up to time t_ms of the client
  void until(int t_ms) {
    while (sim.time_s() < start_s + t_ms * 1e-3 - 1e-9) {
      const int t = static_cast<int>(std::lround((sim.time_s() - start_s) * 1000.0));
      sim.tick(walk_timeline(t));
    }
  }
  // the trunk in the sport frame (fixed when the client started)
  Eigen::Vector2d sport_xy() {
    const Eigen::Vector2d d = sim.true_xy() - origin;
    const double c = std::cos(origin_yaw), s = std::sin(origin_yaw);
    return {c * d.x() + s * d.y(), -s * d.x() + c * d.y()};
  }

  AlienGoSim sim;
  double start_s = 0.0;
  Eigen::Vector2d origin;
  double origin_yaw = 0.0;
};

TEST_F(AlienGoWalkTimeline, EveryStageDoesWhatTheExampleAsksOnTheSimulatorsTruth) {
  // 1: force stand, roll 0.7 asked: reached up to the QP stand's documented clamp (0.52)
  until(1950);
  EXPECT_EQ(sim.session().mode(), 1);
  EXPECT_EQ(sim.status().mode, static_cast<int>(ModeId::QpStand));
  EXPECT_NEAR(sim.true_rpy().x(), QpStandRanges{}.roll.upper, 0.05);
  until(2950);
  EXPECT_NEAR(sim.true_rpy().x(), 0.0, 0.03);
  // pitch 0.4 asked: its clamp 0.3
  until(3950);
  EXPECT_NEAR(sim.true_rpy().y(), QpStandRanges{}.pitch.upper, 0.05);
  // yaw 0.5 (relative, within the clamp)
  const double yaw_before = sim.true_rpy().z();
  until(5950);
  EXPECT_NEAR(sim.true_rpy().z() - yaw_before, 0.5, 0.08);
  // body height +0.05, then -0.15 (clamped at the stand's lowest)
  until(8950);
  EXPECT_NEAR(sim.true_height(), kDefaultBodyHeightM + 0.05, 0.02);
  until(9950);
  EXPECT_LT(sim.true_height(), kDefaultBodyHeightM - 0.04);
  // 2: trot forward turning left, then backward
  until(11000);
  const Eigen::Vector2d before_trot = sport_xy();
  const double yaw_before_trot = sim.true_rpy().z();
  until(13000);
  EXPECT_GT((sport_xy() - before_trot).norm(), 0.2);
  EXPECT_GT(sim.true_rpy().z() - yaw_before_trot, 0.3);
  const Eigen::Vector2d before_back = sport_xy();
  const double heading = sim.true_rpy().z();
  until(15000);
  const Eigen::Vector2d back = sport_xy() - before_back;
  EXPECT_LT(back.x() * std::cos(heading) + back.y() * std::sin(heading), -0.15) << "did not walk backwards";
  // 0: the trot stops by itself
  until(16950);
  EXPECT_TRUE(sim.all_feet_down());
  EXPECT_LT(std::hypot(sim.truth().velocity_world[0], sim.truth().velocity_world[1]), 0.05);
  // 3: walks to (1, 0) of the sport frame, heading 0, body 5 cm lower
  until(22950);
  EXPECT_LT((sport_xy() - Eigen::Vector2d(1.0, 0.0)).norm(), 0.15) << sport_xy().transpose();
  EXPECT_NEAR(sim.true_height(), kDefaultBodyHeightM - 0.05, 0.025);
  // 2 with the stair gait: forward 0.1 m/s for 7 s, back 0.1 m/s for 8 s
  until(25000);
  const double x_stairs = sport_xy().x();
  until(32000);
  EXPECT_GT(sport_xy().x() - x_stairs, 0.45);
  until(40000);
  EXPECT_LT(sport_xy().x() - x_stairs, 0.0);
  // 1 stops the stair gait
  until(41950);
  EXPECT_TRUE(sim.all_feet_down());
  // 5 stand down, 6 stand up, 5 again, 7 damping, 5, 6, 1
  until(43950);
  EXPECT_LT(sim.true_height(), 0.13);
  until(45950);
  EXPECT_GT(sim.true_height(), 0.2);
  until(50950);
  EXPECT_EQ(sim.status().mode, static_cast<int>(ModeId::PureDamper));
  EXPECT_LT(sim.true_height(), 0.1);
  until(54950);
  EXPECT_GT(sim.true_height(), 0.2);
  until(56950);
  EXPECT_EQ(sim.session().mode(), 1);
  // 3 back to (0, 0)
  until(65000);
  EXPECT_LT(sport_xy().norm(), 0.15) << sport_xy().transpose();
  EXPECT_GT(sim.true_height(), 0.18);
  EXPECT_LT(std::abs(sim.true_rpy().x()) + std::abs(sim.true_rpy().y()), 0.2);
}

}  // namespace
}  // namespace cerebellum
