// The robot's MuJoCo model and data, loaded for a test's own checks.
#pragma once

#include <mujoco/mujoco.h>

#include <string>

namespace cerebellum::testing {

inline std::string robot_model_path() { return std::string(CEREBELLUM_MODEL_DIR) + "/cyberdog2.xml"; }

struct MujocoModel {
  MujocoModel() {
    char error[1000] = "";
    m = mj_loadXML(robot_model_path().c_str(), nullptr, error, sizeof(error));
    d = mj_makeData(m);
  }
  ~MujocoModel() {
    mj_deleteData(d);
    mj_deleteModel(m);
  }
  MujocoModel(const MujocoModel&) = delete;
  MujocoModel& operator=(const MujocoModel&) = delete;
  mjModel* m = nullptr;
  mjData* d = nullptr;
};

}  // namespace cerebellum::testing
