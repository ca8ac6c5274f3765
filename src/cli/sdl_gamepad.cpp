#include "cli/sdl_gamepad.hpp"

#include <SDL.h>

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace cerebellum {
namespace {

// the SDL button of each PadButton, in PadButton's order
constexpr std::array<SDL_GameControllerButton, kPadButtonCount> kSdlButtons{SDL_CONTROLLER_BUTTON_A,
                                                                            SDL_CONTROLLER_BUTTON_B,
                                                                            SDL_CONTROLLER_BUTTON_X,
                                                                            SDL_CONTROLLER_BUTTON_Y,
                                                                            SDL_CONTROLLER_BUTTON_LEFTSHOULDER,
                                                                            SDL_CONTROLLER_BUTTON_RIGHTSHOULDER};

std::optional<std::size_t> pad_button(Uint8 sdl_button) {
  for (std::size_t i = 0; i < kSdlButtons.size(); ++i) {
    if (kSdlButtons[i] == sdl_button) return i;
  }
  return std::nullopt;
}

double axis(SDL_GameController* controller, SDL_GameControllerAxis which) {
  return std::clamp(SDL_GameControllerGetAxis(controller, which) / 32767.0, -1.0, 1.0);
}

}  // namespace

SdlGamepad::SdlGamepad() {
  // a pad's events must reach us while no window has the focus (there is none)
  SDL_SetHint(SDL_HINT_JOYSTICK_ALLOW_BACKGROUND_EVENTS, "1");
  if (SDL_Init(SDL_INIT_GAMECONTROLLER) != 0) {
    throw std::runtime_error(std::string("SDL cannot start its game controllers: ") + SDL_GetError());
  }
}

SdlGamepad::~SdlGamepad() {
  if (controller_ != nullptr) SDL_GameControllerClose(controller_);
  SDL_Quit();
}

std::string SdlGamepad::name() const {
  const char* name = controller_ != nullptr ? SDL_GameControllerName(controller_) : nullptr;
  return name != nullptr ? name : "gamepad";
}

PadEvent SdlGamepad::poll() {
  SDL_Event event;
  if (SDL_PollEvent(&event) == 0) return PadEvent::None;
  switch (event.type) {
    case SDL_CONTROLLERDEVICEADDED:
      if (controller_ != nullptr) return PadEvent::None;  // one pad drives; others are ignored
      controller_ = SDL_GameControllerOpen(event.cdevice.which);
      if (controller_ == nullptr) return PadEvent::None;
      instance_id_ = SDL_JoystickInstanceID(SDL_GameControllerGetJoystick(controller_));
      pressed_ = {};
      return PadEvent::Plugged;
    case SDL_CONTROLLERDEVICEREMOVED:
      if (controller_ == nullptr || event.cdevice.which != instance_id_) return PadEvent::None;
      SDL_GameControllerClose(controller_);
      controller_ = nullptr;
      instance_id_ = -1;
      return PadEvent::Unplugged;
    case SDL_CONTROLLERBUTTONDOWN:
      if (controller_ == nullptr || event.cbutton.which != instance_id_) return PadEvent::None;
      if (const std::optional<std::size_t> button = pad_button(event.cbutton.button)) {
        pressed_[*button] = true;
        return PadEvent::Pressed;
      }
      return PadEvent::None;
    default: return PadEvent::None;
  }
}

PadState SdlGamepad::sample() {
  PadState pad;
  if (controller_ != nullptr) {
    pad.left_x = axis(controller_, SDL_CONTROLLER_AXIS_LEFTX);
    pad.left_y = -axis(controller_, SDL_CONTROLLER_AXIS_LEFTY);  // SDL reads pushed forward as negative
    pad.right_x = axis(controller_, SDL_CONTROLLER_AXIS_RIGHTX);
    pad.right_y = -axis(controller_, SDL_CONTROLLER_AXIS_RIGHTY);
    pad.left_trigger = axis(controller_, SDL_CONTROLLER_AXIS_TRIGGERLEFT);  // SDL: 0 released .. 32767
    pad.right_trigger = axis(controller_, SDL_CONTROLLER_AXIS_TRIGGERRIGHT);
  }
  pad.pressed = pressed_;
  pressed_ = {};
  return pad;
}

}  // namespace cerebellum
