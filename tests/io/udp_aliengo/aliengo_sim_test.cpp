// The AlienGo sport session driving the MC in lockstep, judged on the simulator's truth: the
// recovery sequence (7 then 8), the refused moves, the streaming timeout, and arbitration with an
// LCM client (the walk example's whole timeline: aliengo_walk_timeline_test.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "io/udp_aliengo/aliengo_sim.hpp"
#include "io/udp_aliengo/aliengo_wire.hpp"
#include "modes/command_ranges.hpp"

namespace cerebellum {
namespace {

using testing::AlienGoSim;
using testing::high_cmd;

// the trunk's height lying damped in the simulation: 0.059 m measured (the belly on the ground),
// with room for where the legs come to rest
constexpr double kLyingHeightM = 0.06;
constexpr double kLyingToleranceM = 0.03;

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

// what HighState says, through the real encoder and decoder
AlienGoFeedback high_state(AlienGoSim& sim) {
  const CycleRecord& record = sim.mc.loop().last_cycle();
  std::uint8_t bytes[kHighStateBytes];
  encode_high_state(make_feedback(record.state, record.high_level.aliengo_mode, record.high_level.aliengo_frame),
                    bytes);
  AlienGoFeedback feedback;
  EXPECT_TRUE(decode_high_state(bytes, sizeof bytes, feedback));
  return feedback;
}

TEST(AlienGoSim, HighStatePositionReadsTheModeThreeTargetOnceTheRobotHasWalkedToItInALaterSportFrame) {
  AlienGoSim sim;
  sim.idle(3.0);
  // a first session walks forward turning left, then falls silent: the robot lies down and the
  // session ends, away from where the MC started and turned
  AlienGoCommand walk = high_cmd(2);
  walk.velocity = {0.4f, 0.0f};
  walk.yaw_speed = 0.4f;
  sim.stream(high_cmd(0), 0.5);
  sim.stream(walk, 3.0);
  sim.silence(6.0);
  ASSERT_FALSE(sim.session().active());
  // the next HighCmd starts a new session: its sport frame is where the trunk is now
  sim.tick(high_cmd(0));
  const Eigen::Vector2d origin = sim.true_xy();
  const double origin_yaw = sim.true_rpy().z();
  const double origin_z = sim.true_height();
  ASSERT_GT(sim.state().position_world.head<2>().norm(), 0.5) << "the MC's odometry frame is another frame";
  ASSERT_GT(std::abs(origin_yaw), 0.5);
  sim.stream(high_cmd(0), 4.0);
  AlienGoCommand go = high_cmd(3);
  go.position = {0.5f, 0.0f};
  sim.stream(go, 8.0);
  // the robot is at the target on the simulator's truth, in the sport frame
  const Eigen::Vector2d d = sim.true_xy() - origin;
  const double c = std::cos(origin_yaw), s = std::sin(origin_yaw);
  const Eigen::Vector2d truth_sport(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
  EXPECT_LT((truth_sport - Eigen::Vector2d(0.5, 0.0)).norm(), 0.1) << truth_sport.transpose();
  // and HighState.position reads the target there (mode 3 stands within 3 cm of its odometry),
  // and the truth within the odometry's drift; z from the trunk's height when the session started
  const AlienGoFeedback state = high_state(sim);
  EXPECT_EQ(state.mode, 3);
  EXPECT_NEAR(state.position.x(), 0.5, 0.05) << state.position.transpose();
  EXPECT_NEAR(state.position.y(), 0.0, 0.05) << state.position.transpose();
  EXPECT_LT((state.position.head<2>() - truth_sport).norm(), 0.1);
  EXPECT_NEAR(state.position.z(), sim.true_height() - origin_z, 0.03);
}

TEST(AlienGoSim, TheSeedsSitDownSequenceTwoOneSixFiveSevenRunsToDampingWithTheRobotLying) {
  AlienGoSim sim;
  sim.idle(3.0);
  sim.stream(high_cmd(0), 0.5);
  AlienGoCommand walk = high_cmd(2);
  walk.velocity = {0.2f, 0.0f};
  sim.stream(walk, 2.0);
  for (int mode : {1, 6, 5, 7}) {
    sim.tick(high_cmd(mode));
    EXPECT_FALSE(sim.refused) << mode;
    sim.stream(high_cmd(mode), 2.0);
    EXPECT_EQ(sim.session().mode(), mode);
    EXPECT_EQ(sim.reported_mode(), mode);
    if (mode == 1 || mode == 6) {
      EXPECT_GT(sim.true_height(), 0.2) << mode;
    }
    if (mode == 5) {
      EXPECT_LT(sim.true_height(), 0.13) << "lies down in position control";
    }
  }
  EXPECT_EQ(sim.status().mode, static_cast<int>(ModeId::PureDamper));
  EXPECT_EQ(sim.status().gait_id, 0);
  EXPECT_NEAR(sim.true_height(), kLyingHeightM, kLyingToleranceM);
  EXPECT_LT(std::abs(sim.true_rpy().x()) + std::abs(sim.true_rpy().y()), 0.2);
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
