// The viewer's keys as a pad (teleop/keyboard_pad): held keys deflect the sticks fully, presses
// are kept until the next sample, the help and docs/driving.md come from the one table.
#include "teleop/keyboard_pad.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace cerebellum {
namespace {

TEST(KeyboardPad, HoldingWPushesTheLeftStickFullyForwardAndReleasingItCentresTheStick) {
  KeyboardPad keys;
  EXPECT_TRUE(keys.key('W', true));
  PadState pad = keys.sample();
  EXPECT_EQ(pad.left_y, 1.0);
  EXPECT_EQ(pad.left_x, 0.0);
  pad = keys.sample();
  EXPECT_EQ(pad.left_y, 1.0) << "a held key stays down from sample to sample";
  keys.key('W', false);
  EXPECT_EQ(keys.sample().left_y, 0.0);
}

TEST(KeyboardPad, EachDrivingKeyMovesTheAxisItsRowNamesTheWayAPersonExpects) {
  KeyboardPad keys;
  keys.key('A', true);  // left: the stick's x negative
  keys.key('E', true);  // turn right: the right stick's x positive
  keys.key('T', true);  // head up: the right stick up
  keys.key('R', true);  // body up: the right trigger
  const PadState pad = keys.sample();
  EXPECT_EQ(pad.left_x, -1.0);
  EXPECT_EQ(pad.right_x, 1.0);
  EXPECT_EQ(pad.right_y, 1.0);
  EXPECT_EQ(pad.right_trigger, 1.0);
  EXPECT_EQ(pad.left_trigger, 0.0);
}

TEST(KeyboardPad, OppositeKeysHeldTogetherCancel) {
  KeyboardPad keys;
  keys.key('W', true);
  keys.key('S', true);
  EXPECT_EQ(keys.sample().left_y, 0.0);
}

TEST(KeyboardPad, APressIsKeptUntilTheNextSampleEvenWhenTheKeyIsAlreadyUpThenForgotten) {
  KeyboardPad keys;
  EXPECT_FALSE(keys.pressed_since_sample());
  keys.key(' ', true);
  keys.key(' ', false);
  EXPECT_TRUE(keys.pressed_since_sample());
  PadState pad = keys.sample();
  EXPECT_TRUE(pad.pressed[static_cast<std::size_t>(PadButton::B)]);
  EXPECT_FALSE(keys.pressed_since_sample());
  pad = keys.sample();
  EXPECT_FALSE(pad.pressed[static_cast<std::size_t>(PadButton::B)]);
}

TEST(KeyboardPad, LosingTheFocusReleasesEveryHeldKey) {
  KeyboardPad keys;
  keys.key('W', true);
  keys.key('Q', true);
  keys.release_all();
  const PadState pad = keys.sample();
  EXPECT_EQ(pad.left_y, 0.0);
  EXPECT_EQ(pad.right_x, 0.0);
}

TEST(KeyboardPad, KeysThatDoNotDriveAreLeftToTheWindow) {
  KeyboardPad keys;
  EXPECT_FALSE(keys.key('Z', true));
  EXPECT_FALSE(keys.key(256, true));  // GLFW's Escape
}

TEST(KeyboardPad, EveryButtonOfThePadsMappingHasOneKeyAndNoKeyDoesTwoThings) {
  std::set<int> codes;
  for (const AxisKey& key : kAxisKeys) EXPECT_TRUE(codes.insert(key.key_code).second) << key.key_name;
  for (const ButtonKey& key : kButtonKeys) EXPECT_TRUE(codes.insert(key.key_code).second) << key.key_name;
  for (const ButtonBinding& binding : kButtonBindings) {
    int keys_for_button = 0;
    for (const ButtonKey& key : kButtonKeys) keys_for_button += key.button == binding.button ? 1 : 0;
    EXPECT_EQ(keys_for_button, 1) << binding.button_name;
  }
}

TEST(KeyboardPad, TheHelpNamesEveryKeyAndWhatItsButtonDoes) {
  const std::string help = keyboard_mapping_help();
  for (const AxisKey& key : kAxisKeys) EXPECT_NE(help.find(key.key_name), std::string::npos) << key.key_name;
  for (const ButtonBinding& binding : kButtonBindings) EXPECT_NE(help.find(binding.what), std::string::npos);
  EXPECT_NE(help.find("space  damp (7/0)"), std::string::npos) << help;
}

// docs/driving.md shows the keys as the viewer's overlay does: the page cannot drift from the code
TEST(KeyboardPad, DrivingDocsShowTheKeysExactlyAsTheViewerShowsThem) {
  std::ifstream in(std::filesystem::path(CEREBELLUM_SOURCE_DIR) / "docs" / "driving.md");
  ASSERT_TRUE(in) << "docs/driving.md";
  std::ostringstream page;
  page << in.rdbuf();
  EXPECT_NE(page.str().find(keyboard_mapping_help()), std::string::npos)
      << "paste the viewer's key help into docs/driving.md:\n"
      << keyboard_mapping_help();
}

}  // namespace
}  // namespace cerebellum
