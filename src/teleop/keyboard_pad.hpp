// The viewer's keys as a gamepad, for a person without one: held keys push the sticks and triggers
// fully, key presses press the pad's buttons, and the pad's mapping (pad_mapping) makes the commands,
// so the keyboard and the pad drive alike. The tables below are the one home of the keys: the
// viewer's overlay help and docs/driving.md read them.
#pragma once

#include <array>
#include <cstddef>
#include <string>

#include "teleop/pad_mapping.hpp"

namespace cerebellum {

// key codes: the printable keys' ASCII codes (upper-case letters, digits, space), which are also
// GLFW's key codes for them (GLFW_KEY_W == 'W', GLFW_KEY_SPACE == ' ')
enum class PadAxis : std::size_t { LeftX, LeftY, RightX, RightY, LeftTrigger, RightTrigger, Count };
inline constexpr std::size_t kPadAxisCount = static_cast<std::size_t>(PadAxis::Count);

struct AxisKey {
  int key_code;
  const char* key_name;
  PadAxis axis;
  double deflection;  // held: the axis at this value (sticks' up and right positive, as PadState)
};
inline constexpr std::array<AxisKey, 10> kAxisKeys{{
    {'W', "W", PadAxis::LeftY, 1.0},
    {'S', "S", PadAxis::LeftY, -1.0},
    {'A', "A", PadAxis::LeftX, -1.0},
    {'D', "D", PadAxis::LeftX, 1.0},
    {'Q', "Q", PadAxis::RightX, -1.0},
    {'E', "E", PadAxis::RightX, 1.0},
    {'T', "T", PadAxis::RightY, 1.0},
    {'G', "G", PadAxis::RightY, -1.0},
    {'R', "R", PadAxis::RightTrigger, 1.0},
    {'F', "F", PadAxis::LeftTrigger, 1.0},
}};

struct ButtonKey {
  int key_code;
  const char* key_name;
  PadButton button;  // what it does is the button's binding (kButtonBindings)
};
inline constexpr std::array<ButtonKey, 6> kButtonKeys{{
    {' ', "space", PadButton::B},
    {'1', "1", PadButton::A},
    {'2', "2", PadButton::X},
    {'3', "3", PadButton::Y},
    {'4', "4", PadButton::RightShoulder},
    {'5', "5", PadButton::LeftShoulder},
}};

class KeyboardPad {
 public:
  // a key went down (down) or up; false when the key is not a driving key
  bool key(int key_code, bool down);
  // every key up (the window lost the keyboard: a key released elsewhere is never seen)
  void release_all();
  // true when a button was pressed since the last sample (the client sends it at once)
  bool pressed_since_sample() const;
  // the pad as the keys hold it; the presses since the last sample, then forgotten
  PadState sample();

 private:
  std::array<bool, kAxisKeys.size()> held_{};
  std::array<bool, kPadButtonCount> pressed_{};
};

// the keys as a person reads them (the viewer's help overlay, docs/driving.md)
std::string keyboard_mapping_help();

}  // namespace cerebellum
