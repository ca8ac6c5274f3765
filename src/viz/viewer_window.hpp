// The live 3D window (GLFW + MuJoCo's renderer). Runs in the main thread and only draws
// snapshots; what the person asks for (pause, slow motion, quit, a push, the other keys) is read
// back by the caller. Mouse as in MuJoCo's simulate: left drag rotates, right drag moves, scroll
// zooms; ctrl + right drag pulls the trunk (horizontal plane; with shift, vertical plane). The keys
// the window does not use itself are handed to the caller as they come (the keyboard drives the
// robot: teleop/keyboard_pad), with their help shown under the window's own.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "backend/push_request.hpp"
#include "viz/scene_renderer.hpp"

struct GLFWwindow;

namespace cerebellum {

// a key the window does not use: GLFW's key code (printable keys: their upper-case ASCII code)
struct ViewerKey {
  int key_code = 0;
  bool down = false;  // pressed, or released
};

struct ViewerControls {
  bool paused = false;
  bool slow_motion = false;  // 0.25x the run's speed
  bool quit = false;         // Esc or the window closed
};

class ViewerWindow {
 public:
  // throws std::runtime_error naming the reason when no window can be opened (e.g. no display)
  // more_help: the help of the keys handed to the caller, shown under the window's own
  ViewerWindow(const mjModel* model, const std::string& title, const std::string& more_help, int width = 1280,
               int height = 800);
  ~ViewerWindow();
  ViewerWindow(const ViewerWindow&) = delete;
  ViewerWindow& operator=(const ViewerWindow&) = delete;

  // handles pending keyboard and mouse events
  void poll();
  const ViewerControls& controls() const { return controls_; }
  // true once after pause or slow motion changed (the loop must take up the new pace)
  bool take_pace_change();
  PushRequest push() const;
  // the keys pressed and released since the last call, in order; focus_lost: the window lost the
  // keyboard since the last call (keys held then are released where the window cannot see it)
  std::vector<ViewerKey> take_keys(bool& focus_lost);

  // draws the snapshot with the status overlay (run_state and keys_state: its last rows) and shows it
  void draw(const SimSnapshot& snapshot, const std::string& run_state, const std::string& keys_state);
  // draws like draw() and also saves the frame to a .png file (through ffmpeg); false on failure
  bool draw_and_save(const SimSnapshot& snapshot, const std::string& run_state, const std::string& keys_state,
                     const std::string& png_path);

 private:
  static void on_key(GLFWwindow* window, int key, int scancode, int action, int mods);
  static void on_mouse_button(GLFWwindow* window, int button, int action, int mods);
  static void on_cursor(GLFWwindow* window, double x, double y);
  static void on_scroll(GLFWwindow* window, double dx, double dy);
  static void on_focus(GLFWwindow* window, int focused);
  mjrRect render(const SimSnapshot& snapshot, const std::string& run_state, const std::string& keys_state);

  GLFWwindow* window_ = nullptr;
  std::unique_ptr<SceneRenderer> renderer_;
  mjvPerturb perturbation_;
  ViewerControls controls_;
  bool pace_changed_ = false;
  std::string help_;
  std::vector<ViewerKey> keys_;
  bool focus_lost_ = false;
  double cursor_x_ = 0.0;
  double cursor_y_ = 0.0;
};

}  // namespace cerebellum
