// The AlienGo sport session driving the MC in lockstep, judged on the simulator's truth: the
// recovery sequence (7 then 8), the refused moves, the streaming timeout, and arbitration with an
// LCM client (the walk example's whole timeline: aliengo_walk_timeline_test.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "io/udp_aliengo/aliengo_sim.hpp"
#include "modes/command_ranges.hpp"

namespace cerebellum {
namespace {

using testing::AlienGoSim;
using testing::high_cmd;

TEST(AlienGoSim, DampingThenRecoveryStandsTheRobotUpAgain) {
  AlienGoSim sim;
  sim.idle(3.0);
  sim.stream(high_cmd(0), 1.0);
  sim.stream(high_cmd(7), 2.0);
  EXPECT_LT(sim.true_height(), 0.1);
  sim.stream(high_cmd(8), 4.0);
  EXPECT_EQ(sim.session().mode(), 8);
  EXPECT_GT(sim.true_height(), 0.2);
  EXPECT_TRUE(sim.all_feet_down());
}

TEST(AlienGoSim, IllegalMovesAndPathWalkingLeaveTheRobotWhereItIs) {
  AlienGoSim sim;
  sim.idle(3.0);
  sim.stream(high_cmd(0), 1.0);
  // 0 -> 5 is not a move of the vendor's table; 4 is reserved
  for (int mode : {5, 6, 8, 4}) {
    sim.tick(high_cmd(mode));
    EXPECT_TRUE(sim.refused) << mode;
    sim.stream(high_cmd(mode), 0.5);
    EXPECT_EQ(sim.session().mode(), 0) << mode;
    EXPECT_GT(sim.true_height(), 0.2) << mode;
  }
  // 8 only after 7: from 1 it stays
  sim.stream(high_cmd(1), 1.0);
  sim.tick(high_cmd(8));
  EXPECT_TRUE(sim.refused);
  EXPECT_EQ(sim.session().mode(), 1);
}

TEST(AlienGoSim, ASilentClientsRobotStopsWalkingStandsLiesDownAndIsDampedLying) {
  AlienGoSim sim;
  sim.idle(3.0);
  AlienGoCommand walk = high_cmd(2);
  walk.velocity = {0.5f, 0.0f};
  sim.stream(high_cmd(0), 0.5);
  sim.stream(walk, 3.0);
  ASSERT_GT(std::hypot(sim.truth().velocity_world[0], sim.truth().velocity_world[1]), 0.3);
  // the stream stops: it stands within the hold, all feet down and at rest
  sim.silence(1.8);
  EXPECT_EQ(sim.status().mode, static_cast<int>(ModeId::Locomotion));
  EXPECT_EQ(sim.status().gait_id, 1);
  EXPECT_TRUE(sim.all_feet_down());
  EXPECT_LT(std::hypot(sim.truth().velocity_world[0], sim.truth().velocity_world[1]), 0.05);
  EXPECT_GT(sim.true_height(), 0.2);
  // held: it lies down in position control, upright
  sim.silence(2.2);
  EXPECT_EQ(sim.status().mode, static_cast<int>(ModeId::PureDamper));
  EXPECT_EQ(sim.status().gait_id, 1);
  EXPECT_LT(sim.true_height(), 0.14);
  // then no more heartbeats: the MC's timeout damps the lying robot and the session ends
  sim.silence(1.5);
  EXPECT_EQ(sim.status().mode, static_cast<int>(ModeId::PureDamper));
  EXPECT_EQ(sim.status().gait_id, 0);
  EXPECT_FALSE(sim.session().active());
  sim.silence(2.0);
  EXPECT_LT(sim.true_height(), 0.12);
  EXPECT_LT(std::abs(sim.true_rpy().x()) + std::abs(sim.true_rpy().y()), 0.3);
}

}  // namespace
}  // namespace cerebellum

namespace cerebellum {
namespace {

TEST(AlienGoArbitration, AnLcmClientWalkingHoldsTheRobotUntilSilentThenTheUdpClientTakesOver) {
  testing::AlienGoSim sim;
  sim.idle(3.0);
  // the CyberDog2 client walks forward at 0.3 m/s, heartbeating every 0.1 s
  HighLevelCommand lcm_walk;
  lcm_walk.mode = static_cast<int>(ModeId::Locomotion);
  lcm_walk.gait_id = 3;
  lcm_walk.vel_des = {0.3f, 0.0f, 0.0f};
  lcm_walk.life_count = 1;
  // the AlienGo client streams "walk sideways" at the same time
  AlienGoCommand udp_walk = testing::high_cmd(2);
  udp_walk.velocity = {0.0f, 0.3f};
  const double x0 = sim.true_xy().x(), y0 = sim.true_xy().y();
  double next_heartbeat_s = 0.0;
  const double end = sim.time_s() + 3.0;
  while (sim.time_s() < end) {
    if (sim.time_s() >= next_heartbeat_s) {
      sim.mc.machine().submit(lcm_walk, sim.time_s(), HighLevelSource::CyberDog2Lcm);
      next_heartbeat_s = sim.time_s() + 0.1;
    }
    sim.tick(udp_walk);
  }
  EXPECT_EQ(sim.mc.machine().holder(), HighLevelSource::CyberDog2Lcm);
  EXPECT_GT(sim.true_xy().x() - x0, 0.5) << "the holder's walk runs";
  EXPECT_LT(std::abs(sim.true_xy().y() - y0), 0.1) << "the other client's walk does not";
  EXPECT_GT(sim.mc.machine().counters(HighLevelSource::AlienGoUdp).refused_not_holder.load(), 1000u);
  // the LCM client goes silent: damped after its timeout, then the UDP client holds the robot,
  // which stands up (sport mode starts standing) and walks sideways
  sim.stream(udp_walk, 0.6);
  sim.stream(testing::high_cmd(0), 4.0);
  EXPECT_EQ(sim.mc.machine().holder(), HighLevelSource::AlienGoUdp);
  EXPECT_GT(sim.true_height(), 0.2);
  const double y1 = sim.true_xy().y();
  sim.stream(udp_walk, 3.0);
  EXPECT_GT(sim.true_xy().y() - y1, 0.4);
}

}  // namespace
}  // namespace cerebellum
