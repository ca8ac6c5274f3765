// Draws the simulated robot with MuJoCo's renderer from snapshots. Owns a copy of the model and
// its own mjData, so it never touches the loop's simulation. Every call needs the same current
// OpenGL context (a window's or an offscreen one) as the constructor.
#pragma once

#include <mujoco/mujoco.h>

#include <cstdint>
#include <string>

#include "viz/overlay_text.hpp"
#include "viz/sim_snapshot.hpp"

namespace cerebellum {

class SceneRenderer {
 public:
  // offscreen_width/height: size of the offscreen buffer (recorder); font_scale: mjtFontScale
  SceneRenderer(const mjModel* model, int offscreen_width, int offscreen_height, int font_scale);
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  // the state to draw next; perturbation: the viewer's push handle, or nullptr
  void update(const SimSnapshot& snapshot, const mjvPerturb* perturbation = nullptr);
  // scene, then the status block top left and a help line bottom right (empty: none)
  void render(const mjrRect& viewport, const OverlayText& status, const std::string& help);
  // rgb rows bottom to top, 3 * width * height bytes
  void read_rgb(const mjrRect& viewport, std::uint8_t* rgb);

  void use_offscreen_buffer();
  void use_window_buffer();
  // tracking camera on the trunk, or a free camera left where it is
  void set_follow(bool follow);
  bool following() const { return camera_.type == mjCAMERA_TRACKING; }

  const mjModel* model() const { return model_; }
  mjData* data() { return data_; }
  mjvScene& scene() { return scene_; }
  mjvCamera& camera() { return camera_; }
  int trunk_body() const { return trunk_body_; }

 private:
  mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
  mjvScene scene_;
  mjvCamera camera_;
  mjvOption option_;
  mjrContext context_;
  int trunk_body_ = 0;
};

}  // namespace cerebellum
