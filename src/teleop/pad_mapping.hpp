// What a gamepad means to the robot (`cerebellum drive`): the pad's sticks and buttons, sampled,
// become the next high-level command. Pure: no SDL here, so the mapping is tested on numbers and the
// printed help and docs/driving.md come from the same table the code reads.
#pragma once

#include <array>
#include <cstddef>
#include <string>

#include "core/high_level_command.hpp"

namespace cerebellum {

// the buttons `cerebellum drive` uses, in SDL's positional (Xbox) names
enum class PadButton : std::size_t { A, B, X, Y, LeftShoulder, RightShoulder, Count };
inline constexpr std::size_t kPadButtonCount = static_cast<std::size_t>(PadButton::Count);

// one sample of the pad. Sticks in [-1, 1], pushed up and pushed right positive (the SDL edge
// flips SDL's y axis, which reads down positive); triggers in [0, 1], 0 released. pressed: went down
// since the previous sample, so a press shorter than the sampling period is not lost
struct PadState {
  double left_x = 0.0;
  double left_y = 0.0;
  double right_x = 0.0;
  double right_y = 0.0;
  double left_trigger = 0.0;
  double right_trigger = 0.0;
  std::array<bool, kPadButtonCount> pressed{};
};

enum class PadAction { Stand, LieDown, Damp, NextGait, Motion, Jump };

// the buttons' actions, once: the mapping, `cerebellum drive`'s help and docs/driving.md read it
struct ButtonBinding {
  PadButton button;
  const char* button_name;
  PadAction action;
  const char* what;
};
inline constexpr std::array<ButtonBinding, 6> kButtonBindings{{
    {PadButton::B, "B", PadAction::Damp, "damp (7/0): the emergency stop, from every mode"},
    {PadButton::A, "A", PadAction::Stand, "stand up (12/0)"},
    {PadButton::X, "X", PadAction::LieDown, "lie down (7/1)"},
    {PadButton::Y, "Y", PadAction::NextGait, "walk; again: the next walking gait"},
    {PadButton::RightShoulder, "RB", PadAction::Motion, "named motion"},
    {PadButton::LeftShoulder, "LB", PadAction::Jump, "jump"},
}};

// the stick's travel that counts as released: a pad's sticks rest off centre by a few percent
inline constexpr double kStickDeadZone = 0.15;
// the motion and the jump the buttons run: shipped ones (config/motions, docs/jumps.md)
inline constexpr int kPadMotionId = 4;  // wag tail
inline constexpr int kPadJumpId = 6;    // up 30 cm: lands where it took off

// what the next command is, and whether it is new (the client then sends it with a new
// life_count) or the one already running (the client repeats it as the heartbeat)
struct DriveStep {
  HighLevelCommand command;
  bool is_new = false;
};

class PadMapping {
 public:
  PadMapping();

  // the command for this sample of the pad
  DriveStep next(const PadState& pad);
  // the last command with every velocity zero: what the robot is left with when the pad goes away
  DriveStep stop();

  // the walking gait the sticks drive (the gait table's id)
  int gait_id() const;

 private:
  DriveStep emit(const HighLevelCommand& command);
  HighLevelCommand walk(const PadState& pad) const;

  std::size_t gait_index_;
  HighLevelCommand last_{};
  bool sent_any_ = false;
};

// the walking gaits Y cycles through, in the gait table's order
int pad_gait_count();
int pad_gait_at(int index);

// a stick axis past the dead zone, rescaled so the drive starts from zero at its edge
double stick_after_dead_zone(double axis);

// the mapping as a person reads it: `cerebellum drive` prints it at start
std::string pad_mapping_help();

}  // namespace cerebellum
