// A headless OpenGL context: EGL on Mesa's surfaceless platform (software rendering with no
// display, no window system). MuJoCo renders into its own offscreen framebuffer inside it.
#pragma once

namespace cerebellum {

class EglOffscreenContext {
 public:
  // throws std::runtime_error saying which step failed and which packages provide it;
  // the context is current in the calling thread afterwards
  EglOffscreenContext();
  ~EglOffscreenContext();
  EglOffscreenContext(const EglOffscreenContext&) = delete;
  EglOffscreenContext& operator=(const EglOffscreenContext&) = delete;

 private:
  void* display_ = nullptr;
  void* context_ = nullptr;
};

}  // namespace cerebellum
