// SDL2's virtual joystick played from a timed script (`cerebellum drive --virtual-pad FILE`): the
// pad a test plugs, presses and unplugs, seen by SdlGamepad exactly as a real one.
#pragma once

#include <chrono>
#include <cstddef>
#include <vector>

#include "cli/virtual_pad_script.hpp"

struct _SDL_Joystick;

namespace cerebellum {

class VirtualPad {
 public:
  // checks the script's controls (std::invalid_argument for a name SDL does not know) and, when it
  // has no plug line, plugs the pad now (SDL must be started: SdlGamepad); std::runtime_error with
  // SDL's reason when it cannot
  explicit VirtualPad(std::vector<VirtualPadEvent> script);
  ~VirtualPad();
  VirtualPad(const VirtualPad&) = delete;
  VirtualPad& operator=(const VirtualPad&) = delete;

  // applies the script's events that are due
  void play();

 private:
  void plug();
  void unplug();

  std::vector<VirtualPadEvent> script_;
  std::size_t next_ = 0;
  std::chrono::steady_clock::time_point started_at_;
  int device_index_ = -1;
  _SDL_Joystick* joystick_ = nullptr;
};

}  // namespace cerebellum
