// The timed script `cerebellum drive --virtual-pad FILE` plays into SDL's virtual joystick, so the
// tests drive the program through the same game-controller path as a real pad. One event a line,
// in seconds after the program started:
//   <seconds> <SDL game-controller name: a, b, leftx, lefty, ...> <value>
//   <seconds> plug     (the pad is plugged at the start when the script has no plug line)
//   <seconds> unplug
// Buttons take 0 or 1; axes take [-1, 1] as SDL reports them (lefty -1: the stick pushed forward).
// '#' starts a comment.
#pragma once

#include <string>
#include <vector>

namespace cerebellum {

struct VirtualPadEvent {
  enum class Kind { Set, Plug, Unplug };
  double at_s = 0.0;
  Kind kind = Kind::Set;
  std::string control;  // of Set
  double value = 0.0;
};

// events in time order; throws std::invalid_argument naming the line
std::vector<VirtualPadEvent> parse_virtual_pad_script(const std::string& text);

}  // namespace cerebellum
