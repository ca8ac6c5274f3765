// The steps of a motion are checked by the modes they run in when the MC's modes are built: a step
// of a mode a motion cannot run, or one its mode refuses, stops the start with the file and step.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "modes/mode_set.hpp"

namespace cerebellum {
namespace {

std::string build_error(const HighLevelCommand& step, std::shared_ptr<const UserGaitProgram> gait = nullptr) {
  ModeSetConfig config;
  Motion motion;
  motion.user_gait = std::move(gait);
  motion.id = 88;
  motion.name = "test";
  motion.origin = "user/88.toml";
  HighLevelCommand fine;
  fine.mode = 21;
  fine.duration = 500;
  motion.steps = {fine, step};
  config.motions.add(motion);
  try {
    ModeSet modes(config);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(MotionSteps, AStepOfAModeAMotionCannotRunStopsTheStart) {
  HighLevelCommand damp;
  damp.mode = 7;
  damp.duration = 500;
  EXPECT_EQ(build_error(damp), "user/88.toml: motion 88, step 2: a motion step runs mode 3, 11, 12 or 21");
}

TEST(MotionSteps, AStepItsModeRefusesStopsTheStartWithTheModesReason) {
  HighLevelCommand two_legs_up;
  two_legs_up.mode = 21;
  two_legs_up.gait_id = 2;
  two_legs_up.contact = 0b1100;
  two_legs_up.duration = 500;
  EXPECT_EQ(build_error(two_legs_up),
            "user/88.toml: motion 88, step 2: mode 21 gait 2 needs one lifted leg in contact (e.g. 0b1110)");
}

TEST(MotionSteps, AUserGaitStepNeedsTheMotionsOwnGait) {
  HighLevelCommand gait;
  gait.mode = 11;
  gait.gait_id = 110;
  gait.duration = 1000;
  EXPECT_EQ(build_error(gait), "user/88.toml: motion 88, step 2: a step of mode 11 gait 110 needs the motion's own user_gait files");
  EXPECT_EQ(build_error(gait, std::make_shared<const UserGaitProgram>()), "");
}

TEST(MotionSteps, AcceptedStepsBuildTheModes) {
  HighLevelCommand stand;
  stand.mode = 3;
  stand.duration = 500;
  EXPECT_EQ(build_error(stand), "");
}

}  // namespace
}  // namespace cerebellum
