// Mode 7 on the simulated robot, judged on the simulator's truth.
#include <gtest/gtest.h>

#include "modes/mode_sim.hpp"

namespace cerebellum::testing {
namespace {

// The vendor's AlienGo walk example gives its stand-down (mode 5 -> 7/1 here) 2 s before the next
// stage; the robot must be down well before that, from each of the stands a client lies it down from
TEST(PureDamperSim, AnActiveLieDownIsDownWellWithinTheTwoSecondsTheVendorWalkExampleGivesIt) {
  for (ModeId from : {ModeId::RecoveryStand, ModeId::QpStand, ModeId::Locomotion}) {
    SCOPED_TRACE(static_cast<int>(from));
    ModeSim sim;
    sim.run(3.0);
    if (from != ModeId::RecoveryStand) sim.send(command(from, from == ModeId::Locomotion ? 3 : 0), 1.0);
    ASSERT_GT(sim.true_height(), 0.2);
    sim.send(command(ModeId::PureDamper, 1), 1.25);
    const double at_deadline_m = sim.true_height();
    EXPECT_EQ(sim.status().order_process_bar, 100);
    // where it comes to rest (the truth long after), not a height typed here
    sim.run(2.0);
    EXPECT_NEAR(at_deadline_m, sim.true_height(), 0.005);
    EXPECT_LT(std::abs(sim.true_rpy().x()) + std::abs(sim.true_rpy().y()), 0.1);
  }
}

}  // namespace
}  // namespace cerebellum::testing
