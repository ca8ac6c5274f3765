#include "cli/virtual_pad.hpp"

#include <SDL.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cerebellum {

VirtualPad::VirtualPad(std::vector<VirtualPadEvent> script)
    : script_(std::move(script)), started_at_(std::chrono::steady_clock::now()) {
  for (const VirtualPadEvent& event : script_) {
    if (event.kind == VirtualPadEvent::Kind::Set &&
        SDL_GameControllerGetButtonFromString(event.control.c_str()) == SDL_CONTROLLER_BUTTON_INVALID &&
        SDL_GameControllerGetAxisFromString(event.control.c_str()) == SDL_CONTROLLER_AXIS_INVALID) {
      throw std::invalid_argument("virtual pad script: '" + event.control +
                                  "' is no SDL game-controller button or axis (a, b, x, y, leftshoulder, leftx, ...)");
    }
  }
  const bool plugged_later = std::any_of(script_.begin(), script_.end(), [](const VirtualPadEvent& event) {
    return event.kind == VirtualPadEvent::Kind::Plug;
  });
  if (!plugged_later) plug();
}

VirtualPad::~VirtualPad() { unplug(); }

void VirtualPad::plug() {
  if (joystick_ != nullptr) return;
  // a game-controller-typed virtual joystick: SDL gives it the standard mapping, button i and axis
  // i being SDL_GameControllerButton i and SDL_GameControllerAxis i
  SDL_VirtualJoystickDesc desc{};
  desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
  desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
  desc.naxes = SDL_CONTROLLER_AXIS_MAX;
  desc.nbuttons = SDL_CONTROLLER_BUTTON_MAX;
  desc.name = "cerebellum virtual pad";
  device_index_ = SDL_JoystickAttachVirtualEx(&desc);
  if (device_index_ < 0) throw std::runtime_error(std::string("cannot attach a virtual pad: ") + SDL_GetError());
  joystick_ = SDL_JoystickOpen(device_index_);
  if (joystick_ == nullptr) throw std::runtime_error(std::string("cannot open the virtual pad: ") + SDL_GetError());
}

void VirtualPad::unplug() {
  if (joystick_ == nullptr) return;
  SDL_JoystickClose(joystick_);
  SDL_JoystickDetachVirtual(device_index_);
  joystick_ = nullptr;
}

void VirtualPad::play() {
  const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_at_).count();
  for (; next_ < script_.size() && script_[next_].at_s <= elapsed_s; ++next_) {
    const VirtualPadEvent& event = script_[next_];
    switch (event.kind) {
      case VirtualPadEvent::Kind::Plug: plug(); break;
      case VirtualPadEvent::Kind::Unplug: unplug(); break;
      case VirtualPadEvent::Kind::Set:
        if (joystick_ == nullptr) break;  // a control moved while unplugged reaches nobody
        if (const SDL_GameControllerButton button = SDL_GameControllerGetButtonFromString(event.control.c_str());
            button != SDL_CONTROLLER_BUTTON_INVALID) {
          SDL_JoystickSetVirtualButton(joystick_, button, event.value > 0.5 ? SDL_PRESSED : SDL_RELEASED);
        } else {
          const SDL_GameControllerAxis axis = SDL_GameControllerGetAxisFromString(event.control.c_str());
          SDL_JoystickSetVirtualAxis(joystick_, axis, static_cast<Sint16>(std::lround(event.value * 32767.0)));
        }
        break;
    }
  }
}

}  // namespace cerebellum
