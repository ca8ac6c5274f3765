#include "viz/viewer_window.hpp"

#include <GLFW/glfw3.h>

#include <stdexcept>
#include <vector>

#include "viz/ffmpeg_pipe.hpp"

namespace cerebellum {
namespace {

// the window's own keys; the others are the caller's (the keyboard drives the robot)
constexpr const char* kHelp = "P  pause\nM  slow motion\nC  follow\nctrl+right drag  push\nEsc  quit";
// a person holding a key down sends one press, not a stream of them
constexpr std::size_t kMaxPendingKeys = 64;

std::string glfw_error() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "no reason given";
}

ViewerWindow& owner(GLFWwindow* window) { return *static_cast<ViewerWindow*>(glfwGetWindowUserPointer(window)); }

}  // namespace

ViewerWindow::ViewerWindow(const mjModel* model, const std::string& title, const std::string& more_help, int width,
                           int height)
    : help_(more_help.empty() ? std::string(kHelp) : std::string(kHelp) + "\n" + more_help) {
  if (!glfwInit()) {
    throw std::runtime_error("viewer: no display to open a window on (" + glfw_error() +
                             "). Run it on a desktop, or under a virtual display: xvfb-run -a cerebellum sim "
                             "--viewer; for a video without any display use --record FILE.mp4");
  }
  glfwWindowHint(GLFW_SAMPLES, 0);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    const std::string reason = glfw_error();
    glfwTerminate();
    throw std::runtime_error("viewer: cannot open an OpenGL window (" + reason + ")");
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);
  renderer_ = std::make_unique<SceneRenderer>(model, 640, 480, mjFONTSCALE_150);
  renderer_->use_window_buffer();
  mjv_defaultPerturb(&perturbation_);

  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, &ViewerWindow::on_key);
  glfwSetMouseButtonCallback(window_, &ViewerWindow::on_mouse_button);
  glfwSetCursorPosCallback(window_, &ViewerWindow::on_cursor);
  glfwSetScrollCallback(window_, &ViewerWindow::on_scroll);
  glfwSetWindowFocusCallback(window_, &ViewerWindow::on_focus);
}

ViewerWindow::~ViewerWindow() {
  renderer_.reset();  // frees GL objects while the context is still current
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void ViewerWindow::poll() {
  glfwPollEvents();
  if (glfwWindowShouldClose(window_)) controls_.quit = true;
}

bool ViewerWindow::take_pace_change() {
  const bool changed = pace_changed_;
  pace_changed_ = false;
  return changed;
}

PushRequest ViewerWindow::push() const {
  PushRequest request;
  request.active = perturbation_.active != 0;
  for (int k = 0; k < 3; ++k) request.target_world[k] = perturbation_.refpos[k];
  return request;
}

std::vector<ViewerKey> ViewerWindow::take_keys(bool& focus_lost) {
  focus_lost = focus_lost_;
  focus_lost_ = false;
  std::vector<ViewerKey> keys;
  keys.swap(keys_);
  return keys;
}

mjrRect ViewerWindow::render(const SimSnapshot& snapshot, const std::string& run_state, const std::string& keys_state) {
  mjrRect viewport{0, 0, 0, 0};
  glfwGetFramebufferSize(window_, &viewport.width, &viewport.height);
  renderer_->update(snapshot, &perturbation_);
  renderer_->render(viewport, status_overlay(snapshot, run_state, keys_state), help_);
  return viewport;
}

void ViewerWindow::draw(const SimSnapshot& snapshot, const std::string& run_state, const std::string& keys_state) {
  render(snapshot, run_state, keys_state);
  glfwSwapBuffers(window_);
}

bool ViewerWindow::draw_and_save(const SimSnapshot& snapshot, const std::string& run_state,
                                 const std::string& keys_state, const std::string& png_path) {
  const mjrRect viewport = render(snapshot, run_state, keys_state);
  std::vector<std::uint8_t> rgb(3 * static_cast<std::size_t>(viewport.width) * viewport.height);
  renderer_->read_rgb(viewport, rgb.data());
  glfwSwapBuffers(window_);
  FfmpegPipe image(png_path, viewport.width, viewport.height, 1.0);
  return image.write_frame(rgb.data()) && image.finish();
}

void ViewerWindow::on_key(GLFWwindow* window, int key, int, int action, int) {
  if (action == GLFW_REPEAT) return;  // a held key stays down until its release
  ViewerWindow& self = owner(window);
  const bool press = action == GLFW_PRESS;
  switch (key) {
    case GLFW_KEY_P:
      if (press) {
        self.controls_.paused = !self.controls_.paused;
        self.pace_changed_ = true;
      }
      break;
    case GLFW_KEY_M:
      if (press) {
        self.controls_.slow_motion = !self.controls_.slow_motion;
        self.pace_changed_ = true;
      }
      break;
    case GLFW_KEY_C:
      if (press) self.renderer_->set_follow(!self.renderer_->following());
      break;
    case GLFW_KEY_ESCAPE:
      if (press) self.controls_.quit = true;
      break;
    default:
      // bounded: the caller takes them every frame
      if (self.keys_.size() < kMaxPendingKeys) self.keys_.push_back({key, press});
      break;
  }
}

void ViewerWindow::on_focus(GLFWwindow* window, int focused) {
  if (!focused) owner(window).focus_lost_ = true;
}

void ViewerWindow::on_mouse_button(GLFWwindow* window, int button, int action, int mods) {
  ViewerWindow& self = owner(window);
  glfwGetCursorPos(window, &self.cursor_x_, &self.cursor_y_);
  const bool push_button = button == GLFW_MOUSE_BUTTON_RIGHT && (mods & GLFW_MOD_CONTROL);
  if (action == GLFW_PRESS && push_button) {
    // the handle starts at the trunk's centre of mass
    self.perturbation_.select = self.renderer_->trunk_body();
    self.perturbation_.skinselect = -1;
    mju_zero3(self.perturbation_.localpos);
    self.perturbation_.active = mjPERT_TRANSLATE;
    mjv_initPerturb(self.renderer_->model(), self.renderer_->data(), &self.renderer_->scene(), &self.perturbation_);
  } else if (action == GLFW_RELEASE && button == GLFW_MOUSE_BUTTON_RIGHT) {
    self.perturbation_.active = 0;
  }
}

void ViewerWindow::on_cursor(GLFWwindow* window, double x, double y) {
  ViewerWindow& self = owner(window);
  const double dx = x - self.cursor_x_;
  const double dy = y - self.cursor_y_;
  self.cursor_x_ = x;
  self.cursor_y_ = y;
  const bool left = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  const bool right = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  const bool middle = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
  if (!left && !right && !middle) return;
  const bool shift =
      glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS || glfwGetKey(window, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
  int height = 1;
  int width = 1;
  glfwGetWindowSize(window, &width, &height);
  const double rel_dx = dx / height;
  const double rel_dy = dy / height;
  if (self.perturbation_.active) {
    mjv_movePerturb(self.renderer_->model(), self.renderer_->data(), shift ? mjMOUSE_MOVE_V : mjMOUSE_MOVE_H, rel_dx,
                    rel_dy, &self.renderer_->scene(), &self.perturbation_);
    return;
  }
  int action = mjMOUSE_ZOOM;
  if (right) {
    action = shift ? mjMOUSE_MOVE_H : mjMOUSE_MOVE_V;
  } else if (left) {
    action = shift ? mjMOUSE_ROTATE_H : mjMOUSE_ROTATE_V;
  }
  mjv_moveCamera(self.renderer_->model(), action, rel_dx, rel_dy, &self.renderer_->scene(), &self.renderer_->camera());
}

void ViewerWindow::on_scroll(GLFWwindow* window, double, double dy) {
  ViewerWindow& self = owner(window);
  mjv_moveCamera(self.renderer_->model(), mjMOUSE_ZOOM, 0.0, -0.05 * dy, &self.renderer_->scene(),
                 &self.renderer_->camera());
}

}  // namespace cerebellum
