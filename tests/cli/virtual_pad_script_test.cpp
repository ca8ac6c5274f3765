// The virtual pad's script (cli/virtual_pad_script): what `cerebellum drive --virtual-pad` plays
#include "cli/virtual_pad_script.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace cerebellum {
namespace {

TEST(VirtualPadScript, ReadsControlsPlugAndUnplugInTimeOrderSkippingComments) {
  const std::vector<VirtualPadEvent> events =
      parse_virtual_pad_script("# a comment\n0.5 plug\n\n0.7 a 1  # stand\n1 lefty -0.575\n2.5 unplug\n");
  ASSERT_EQ(events.size(), 4u);
  EXPECT_EQ(events[0].kind, VirtualPadEvent::Kind::Plug);
  EXPECT_DOUBLE_EQ(events[0].at_s, 0.5);
  EXPECT_EQ(events[1].kind, VirtualPadEvent::Kind::Set);
  EXPECT_EQ(events[1].control, "a");
  EXPECT_DOUBLE_EQ(events[1].value, 1.0);
  EXPECT_EQ(events[2].control, "lefty");
  EXPECT_DOUBLE_EQ(events[2].value, -0.575);
  EXPECT_EQ(events[3].kind, VirtualPadEvent::Kind::Unplug);
  EXPECT_DOUBLE_EQ(events[3].at_s, 2.5);
}

TEST(VirtualPadScript, NamesTheLineOfABadTimeValueOrShape) {
  const auto message = [](const std::string& text) {
    try {
      parse_virtual_pad_script(text);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message("1 a 1\n0.5 a 0\n"), "virtual pad script line 2: times must not go back");
  EXPECT_EQ(message("x a 1\n"), "virtual pad script line 1: 'x' is not a time in seconds");
  EXPECT_EQ(message("1 lefty 2\n"), "virtual pad script line 1: '2' is not a value in [-1, 1]");
  EXPECT_NE(message("1 a\n").find("line 1: expected"), std::string::npos);
}

}  // namespace
}  // namespace cerebellum
