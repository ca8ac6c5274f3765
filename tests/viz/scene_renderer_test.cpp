// Headless rendering of the robot model: the picture has the robot where the camera looks, and
// moving the robot away changes exactly that part of it.
#include "viz/scene_renderer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "viz/egl_offscreen_context.hpp"

namespace cerebellum {
namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};

std::unique_ptr<mjModel, ModelDeleter> load_model() {
  char error[512] = "";
  mjModel* model = mj_loadXML(CEREBELLUM_MODEL_DIR "/cyberdog2.xml", nullptr, error, sizeof error);
  EXPECT_NE(model, nullptr) << error;
  return std::unique_ptr<mjModel, ModelDeleter>(model);
}

// mean absolute difference of two rgb images over the pixel rectangle [x0, x1) x [y0, y1)
double mean_difference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b, int x0, int x1, int y0,
                       int y1) {
  double sum = 0.0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      for (int c = 0; c < 3; ++c) {
        const std::size_t i = 3 * (static_cast<std::size_t>(y) * kWidth + x) + c;
        sum += std::abs(static_cast<int>(a[i]) - static_cast<int>(b[i]));
      }
    }
  }
  return sum / (3.0 * (x1 - x0) * (y1 - y0));
}

TEST(SceneRenderer, DrawsTheRobotWhereTheFollowingCameraLooks) {
  auto model = load_model();
  ASSERT_TRUE(model);
  EglOffscreenContext context;
  SceneRenderer renderer(model.get(), kWidth, kHeight, mjFONTSCALE_50);
  renderer.use_offscreen_buffer();
  const mjrRect viewport{0, 0, kWidth, kHeight};

  SimSnapshot snapshot;
  snapshot.qpos.assign(model->qpos0, model->qpos0 + model->nq);
  snapshot.qvel.assign(static_cast<std::size_t>(model->nv), 0.0);
  std::vector<std::uint8_t> with_robot(3 * kWidth * kHeight);
  renderer.update(snapshot);
  renderer.render(viewport, OverlayText{}, "");
  renderer.read_rgb(viewport, with_robot.data());

  // the same view (free camera left where it was) with the robot 50 m away
  renderer.set_follow(false);
  snapshot.qpos[0] += 50.0;
  std::vector<std::uint8_t> without_robot(3 * kWidth * kHeight);
  renderer.update(snapshot);
  renderer.render(viewport, OverlayText{}, "");
  renderer.read_rgb(viewport, without_robot.data());

  const double centre =
      mean_difference(with_robot, without_robot, kWidth / 3, 2 * kWidth / 3, kHeight / 3, 2 * kHeight / 3);
  const double corners = mean_difference(with_robot, without_robot, 0, kWidth / 8, 0, kHeight / 8);
  EXPECT_GT(centre, 15.0);
  EXPECT_LT(corners, 2.0);
}

}  // namespace
}  // namespace cerebellum
