#include "teleop/keyboard_pad.hpp"

#include <algorithm>

namespace cerebellum {
namespace {

double& axis_of(PadState& pad, PadAxis axis) {
  switch (axis) {
    case PadAxis::LeftX: return pad.left_x;
    case PadAxis::LeftY: return pad.left_y;
    case PadAxis::RightX: return pad.right_x;
    case PadAxis::RightY: return pad.right_y;
    case PadAxis::LeftTrigger: return pad.left_trigger;
    case PadAxis::RightTrigger:
    case PadAxis::Count: break;
  }
  return pad.right_trigger;
}

const char* button_what(PadButton button) {
  for (const ButtonBinding& binding : kButtonBindings) {
    if (binding.button == button) return binding.what;
  }
  return "";
}

// the keys of one axis, "W/S"
std::string axis_keys(PadAxis axis) {
  std::string names;
  for (const AxisKey& key : kAxisKeys) {
    if (key.axis != axis) continue;
    if (!names.empty()) names += "/";
    names += key.key_name;
  }
  return names;
}

}  // namespace

bool KeyboardPad::key(int key_code, bool down) {
  for (std::size_t i = 0; i < kAxisKeys.size(); ++i) {
    if (kAxisKeys[i].key_code != key_code) continue;
    held_[i] = down;
    return true;
  }
  for (const ButtonKey& button : kButtonKeys) {
    if (button.key_code != key_code) continue;
    if (down) pressed_[static_cast<std::size_t>(button.button)] = true;
    return true;
  }
  return false;
}

void KeyboardPad::release_all() { held_.fill(false); }

bool KeyboardPad::pressed_since_sample() const {
  return std::any_of(pressed_.begin(), pressed_.end(), [](bool pressed) { return pressed; });
}

PadState KeyboardPad::sample() {
  PadState pad;
  for (std::size_t i = 0; i < kAxisKeys.size(); ++i) {
    if (!held_[i]) continue;
    double& axis = axis_of(pad, kAxisKeys[i].axis);
    // two opposite keys held cancel: the stick is where their sum puts it
    axis = std::clamp(axis + kAxisKeys[i].deflection, -1.0, 1.0);
  }
  pad.pressed = pressed_;
  pressed_.fill(false);
  return pad;
}

std::string keyboard_mapping_help() {
  std::string out;
  out += axis_keys(PadAxis::LeftY) + "  forward/back\n";
  out += axis_keys(PadAxis::LeftX) + "  left/right\n";
  out += axis_keys(PadAxis::RightX) + "  turn left/right\n";
  out += axis_keys(PadAxis::RightY) + "  head up/down\n";
  out += axis_keys(PadAxis::RightTrigger) + "/" + axis_keys(PadAxis::LeftTrigger) + "  body up/down\n";
  for (const ButtonKey& key : kButtonKeys) {
    out += std::string(key.key_name) + "  " + button_what(key.button) + "\n";
  }
  return out;
}

}  // namespace cerebellum
