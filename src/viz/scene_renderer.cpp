#include "viz/scene_renderer.hpp"

#include <algorithm>
#include <stdexcept>

namespace cerebellum {
namespace {

constexpr int kMaxGeoms = 2000;

}  // namespace

SceneRenderer::SceneRenderer(const mjModel* model, int offscreen_width, int offscreen_height, int font_scale) {
  model_ = mj_copyModel(nullptr, model);
  if (!model_) throw std::runtime_error("renderer: cannot copy the MuJoCo model");
  model_->vis.global.offwidth = offscreen_width;
  model_->vis.global.offheight = offscreen_height;
  // software rendering: a 1024 shadow map looks the same at these sizes and costs far less than 4096
  model_->vis.quality.shadowsize = 1024;
  // no multisampling: it costs a third of a software-rendered frame; the shadows stay (they show
  // where the feet touch)
  model_->vis.quality.offsamples = 0;
  data_ = mj_makeData(model_);
  trunk_body_ = std::max(0, mj_name2id(model_, mjOBJ_BODY, "trunk"));

  mjv_defaultScene(&scene_);
  mjv_defaultCamera(&camera_);
  mjv_defaultOption(&option_);
  mjr_defaultContext(&context_);
  mjv_makeScene(model_, &scene_, kMaxGeoms);
  mjr_makeContext(model_, &context_, font_scale);
  // the floor reflection doubles the cost of a software-rendered frame and adds little
  scene_.flags[mjRND_REFLECTION] = 0;
  option_.flags[mjVIS_PERTFORCE] = 1;

  // close enough that the legs are readable in a 1280x720 frame
  camera_.distance = 1.15;
  camera_.azimuth = 135.0;
  camera_.elevation = -20.0;
  camera_.lookat[2] = 0.2;
  set_follow(true);
}

SceneRenderer::~SceneRenderer() {
  mjr_freeContext(&context_);
  mjv_freeScene(&scene_);
  mj_deleteData(data_);
  mj_deleteModel(model_);
}

void SceneRenderer::update(const SimSnapshot& snapshot, const mjvPerturb* perturbation) {
  const auto nq = static_cast<std::size_t>(model_->nq);
  const auto nv = static_cast<std::size_t>(model_->nv);
  std::copy_n(snapshot.qpos.begin(), std::min(nq, snapshot.qpos.size()), data_->qpos);
  std::copy_n(snapshot.qvel.begin(), std::min(nv, snapshot.qvel.size()), data_->qvel);
  data_->time = snapshot.time_s;
  mju_zero(data_->xfrc_applied, 6 * model_->nbody);
  for (int k = 0; k < 3; ++k) data_->xfrc_applied[6 * trunk_body_ + k] = snapshot.external_force_n[k];
  mj_forward(model_, data_);
  mjvPerturb none;
  mjv_defaultPerturb(&none);
  mjv_updateScene(model_, data_, &option_, perturbation ? perturbation : &none, &camera_, mjCAT_ALL, &scene_);
}

void SceneRenderer::render(const mjrRect& viewport, const OverlayText& status, const std::string& help) {
  mjr_render(viewport, &scene_, &context_);
  // bottom left: the follow camera keeps the robot in the middle, and the sky free
  mjr_overlay(mjFONT_NORMAL, mjGRID_BOTTOMLEFT, viewport, status.titles.c_str(), status.values.c_str(), &context_);
  if (!help.empty()) mjr_overlay(mjFONT_NORMAL, mjGRID_BOTTOMRIGHT, viewport, help.c_str(), nullptr, &context_);
}

void SceneRenderer::read_rgb(const mjrRect& viewport, std::uint8_t* rgb) {
  mjr_readPixels(rgb, nullptr, viewport, &context_);
}

void SceneRenderer::use_offscreen_buffer() { mjr_setBuffer(mjFB_OFFSCREEN, &context_); }

void SceneRenderer::use_window_buffer() { mjr_setBuffer(mjFB_WINDOW, &context_); }

void SceneRenderer::set_follow(bool follow) {
  if (follow) {
    camera_.type = mjCAMERA_TRACKING;
    camera_.trackbodyid = trunk_body_;
  } else {
    camera_.type = mjCAMERA_FREE;
  }
}

}  // namespace cerebellum
