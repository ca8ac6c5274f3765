// The two-leg stand (mode 64) over 10 seeded runs with sensor noise (seeds 301-310, which no
// tuning decision looked at): each rises above 1.3 rad on the hind feet alone, comes down without
// a protection and stands again within 1 cm / 0.05 rad of the stand it started from. Lockstep,
// judged on the simulation's ground truth. A long sweep: the Release stage runs it, the sanitized
// stage leaves it out (label "seeds").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "loop/lockstep_client.hpp"
#include "loop/simulated_robot.hpp"
#include "backend/sim_fixture.hpp"
#include "mc_fixture.hpp"

namespace cerebellum {
namespace {

TEST(McTwoLegStandSeeds, EveryNoisyRunRisesComesDownAndStandsWhereItStood) {
  for (unsigned seed = 301; seed <= 310; ++seed) {
    Mc mc = make_simulated_mc(testing::lying_start(true, seed));
    LockstepClient client(mc);
    client.run(high_level_command(ModeId::RecoveryStand, 0), 3.0);
    client.run(high_level_command(ModeId::PoseControl, 3), 1.0);
    const GroundTruth before = mc.simulation().ground_truth();
    double highest_rad = 0.0;
    bool protected_ = false;
    client.run(high_level_command(ModeId::TwoLegStand, 0), 11.0, [&](const CycleRecord&) {
      highest_rad = std::max(highest_rad, testing::truth_elevation(mc.simulation().ground_truth()));
      const HighLevelStatus& status = mc.machine().status();
      protected_ |= status.mode != 64 || status.switch_status == SwitchStatus::HighDamping;
    });
    const GroundTruth after = mc.simulation().ground_truth();
    const Eigen::Vector3d rpy = testing::truth_rpy(after);
    EXPECT_GT(highest_rad, 1.3) << "seed " << seed;
    EXPECT_FALSE(protected_) << "seed " << seed;
    EXPECT_NEAR(after.position[2], before.position[2], 0.01) << "seed " << seed;
    EXPECT_LT(std::max(std::abs(rpy.x()), std::abs(rpy.y())), 0.05) << "seed " << seed;
    EXPECT_EQ(mc.machine().status().order_process_bar, 100) << "seed " << seed;
  }
}

}  // namespace
}  // namespace cerebellum
