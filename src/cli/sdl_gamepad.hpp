// A gamepad through SDL2's game-controller API (its mapping database, hot-plug): the one place
// `cerebellum drive` touches SDL. It turns the pad into PadState samples and reports plugging.
#pragma once

#include <array>
#include <string>

#include "teleop/pad_mapping.hpp"

struct _SDL_GameController;

namespace cerebellum {

enum class PadEvent { None, Plugged, Unplugged, Pressed };

class SdlGamepad {
 public:
  // starts SDL's game-controller subsystem (no window, no display needed);
  // throws std::runtime_error with SDL's reason when it cannot
  SdlGamepad();
  ~SdlGamepad();
  SdlGamepad(const SdlGamepad&) = delete;
  SdlGamepad& operator=(const SdlGamepad&) = delete;

  // takes one pending SDL event: the first pad plugged (or present at start) is opened, its
  // removal reported; button presses are remembered until the next sample
  PadEvent poll();
  bool connected() const { return controller_ != nullptr; }
  std::string name() const;
  // the sticks now and the presses since the previous sample
  PadState sample();

 private:
  _SDL_GameController* controller_ = nullptr;
  int instance_id_ = -1;
  std::array<bool, kPadButtonCount> pressed_{};
};

}  // namespace cerebellum
