// Stands the simulated robot up with the installed libraries; prints the final trunk height.
#include <cerebellum/loop/control_loop.hpp>
#include <cerebellum/backend/mujoco_backend.hpp>
#include <cerebellum/control/stand_up_controller.hpp>
#include <cerebellum/estimation/kinematic_estimator.hpp>
#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  cerebellum::MujocoBackendConfig config;
  config.model_path = argv[1];
  cerebellum::MujocoBackend backend(config);
  cerebellum::KinematicEstimator estimator;
  cerebellum::StandUpController stand_up(cerebellum::default_stand_up_config());
  cerebellum::ControlLoop loop(backend, estimator, stand_up, cerebellum::GuardLimits{}, 0.002);
  for (int i = 0; i < 1500; ++i) loop.tick();
  std::printf("consumer height %.3f\n", backend.ground_truth().position[2]);
  return backend.ground_truth().position[2] > 0.2 ? 0 : 1;
}
