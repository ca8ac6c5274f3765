// Every jump of mode 16, 20 seeded runs each with sensor noise (seeds 301-320, which no tuning
// decision looked at): no fall, and the robot stands again in the mode. Lockstep, judged on the
// simulation's ground truth. A long sweep: the Release stage runs it, the sanitized stage leaves
// it out (label "seeds").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "loop/lockstep_client.hpp"
#include "loop/simulated_robot.hpp"
#include "backend/sim_fixture.hpp"
#include "modes/jump_mode.hpp"

namespace cerebellum {
namespace {

struct SeededJump {
  bool fell = false;
  bool stood = false;
};

SeededJump jump_with_noise(int gait, unsigned seed) {
  McConfig config = default_config();
  config.startup = Startup::Off;
  config.robot.noise.enabled = true;
  config.robot.noise.seed = seed;
  if (gait == 9) {
    config.robot.model_path = std::string(CEREBELLUM_MODEL_DIR) + "/terrain_stair_down10cm.xml";
    config.robot.initial_height_m = 0.4;
  }
  Mc mc = make_simulated_mc(config);
  LockstepClient client(mc);
  client.run(high_level_command(ModeId::RecoveryStand, 0), 3.0);
  client.run(high_level_command(ModeId::Locomotion, 1), 1.0);
  SeededJump result;
  client.run(high_level_command(ModeId::Jump3d, gait), 4.0, [&](const CycleRecord&) {
    const GroundTruth g = mc.simulation().ground_truth();
    const Eigen::Vector3d rpy = testing::truth_rpy(g);
    result.fell |= std::abs(rpy.x()) > 1.0 || std::abs(rpy.y()) > 1.0 || g.position[2] < 0.1;
  });
  const HighLevelStatus& s = mc.machine().status();
  result.stood = s.mode == 16 && s.gait_id == gait && s.order_process_bar == 100 &&
                 s.switch_status == SwitchStatus::Done && mc.simulation().ground_truth().position[2] > 0.2;
  return result;
}

class EveryJump : public ::testing::TestWithParam<int> {};

TEST_P(EveryJump, LandsWithoutAFallAndStandsAgainInTwentyRunsWithSensorNoise) {
  const int gait = GetParam();
  for (unsigned seed = 301; seed <= 320; ++seed) {
    const SeededJump run = jump_with_noise(gait, seed);
    EXPECT_FALSE(run.fell) << "jump " << gait << ", seed " << seed;
    EXPECT_TRUE(run.stood) << "jump " << gait << ", seed " << seed;
  }
}

INSTANTIATE_TEST_SUITE_P(Jump3d, EveryJump, ::testing::Values(0, 1, 2, 3, 4, 5, 6, 9),
                         [](const ::testing::TestParamInfo<int>& info) {
                           return std::string(find_jump(info.param)->name) == "down a stair"
                                      ? std::string("DownAStair")
                                      : "Jump" + std::to_string(info.param);
                         });

}  // namespace
}  // namespace cerebellum
