#include "viz/egl_offscreen_context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <stdexcept>
#include <string>

namespace cerebellum {
namespace {

// the error of the step that just failed; read before any cleanup call resets it
std::runtime_error failure(const char* step) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(eglGetError()));
  return std::runtime_error(std::string("headless rendering: ") + step + " failed (EGL error " + code +
                            "); it needs Mesa's EGL and software driver (Debian: libegl1 libegl-mesa0 "
                            "libgl1-mesa-dri)");
}

}  // namespace

EglOffscreenContext::EglOffscreenContext() {
  const auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!get_platform_display) throw failure("eglGetPlatformDisplayEXT lookup");
  EGLDisplay display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) throw failure("opening the surfaceless display");
  EGLint major = 0;
  EGLint minor = 0;
  if (!eglInitialize(display, &major, &minor)) throw failure("eglInitialize");
  display_ = display;

  const EGLint config_attributes[] = {EGL_RED_SIZE,
                                      8,
                                      EGL_GREEN_SIZE,
                                      8,
                                      EGL_BLUE_SIZE,
                                      8,
                                      EGL_ALPHA_SIZE,
                                      8,
                                      EGL_DEPTH_SIZE,
                                      24,
                                      EGL_STENCIL_SIZE,
                                      8,
                                      EGL_SURFACE_TYPE,
                                      EGL_PBUFFER_BIT,
                                      EGL_RENDERABLE_TYPE,
                                      EGL_OPENGL_BIT,
                                      EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (!eglChooseConfig(display, config_attributes, &config, 1, &count) || count < 1) {
    const auto error = failure("choosing an RGBA8 / depth24 / stencil8 OpenGL config");
    eglTerminate(display);
    throw error;
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    const auto error = failure("eglBindAPI(OpenGL)");
    eglTerminate(display);
    throw error;
  }
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, nullptr);
  if (context == EGL_NO_CONTEXT) {
    const auto error = failure("eglCreateContext");
    eglTerminate(display);
    throw error;
  }
  context_ = context;
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    const auto error = failure("making the context current without a surface");
    eglDestroyContext(display, context);
    eglTerminate(display);
    throw error;
  }
}

EglOffscreenContext::~EglOffscreenContext() {
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  eglTerminate(display_);
}

}  // namespace cerebellum
