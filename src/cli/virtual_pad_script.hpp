// The timed script `cerebellum drive --virtual-pad FILE` plays into SDL's virtual joystick, so the
// tests drive the program through the same game-controller path as a real pad. One event a line:
//   <seconds after the pad is plugged> <SDL game-controller name: a, b, leftx, lefty, ...> <value>
//   <seconds> unplug
// Buttons take 0 or 1; axes take [-1, 1] as SDL reports them (lefty -1: the stick pushed forward).
// '#' starts a comment.
#pragma once

#include <string>
#include <vector>

namespace cerebellum {

struct VirtualPadEvent {
  double at_s = 0.0;
  std::string control;  // empty: unplug
  double value = 0.0;
};

// events in time order; throws std::invalid_argument naming the line
std::vector<VirtualPadEvent> parse_virtual_pad_script(const std::string& text);

}  // namespace cerebellum
