// The backend's physics step reuses the position and velocity stages that read()'s mj_forward
// computed for the same state. MuJoCo's full mj_step1 would compute them again and normalise the
// trunk's quaternion a second time, which moves its last bits now and then: the simulation must
// stay within rounding of that full step, and a change of the model between a read and the next
// step must be seen by that step.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "backend/mujoco_backend.hpp"
#include "backend/sim_fixture.hpp"
#include "core/joint_layout.hpp"

namespace cerebellum {
namespace {

double largest_difference(const double* a, const double* b, int n) {
  double largest = 0.0;
  for (int i = 0; i < n; ++i) largest = std::max(largest, std::abs(a[i] - b[i]));
  return largest;
}

TEST(MujocoBackendStep, ReusingTheSensorsForwardStaysWithinRoundingOfMujocosFullStepAndSeesAChangedModel) {
  MujocoBackend backend(testing::sim_config(0.3));
  // the reference: the same model and state, stepped by MuJoCo's own full step
  mjModel* m = mj_copyModel(nullptr, backend.model());
  mjData* d = mj_makeData(m);
  mj_copyData(d, m, backend.data());
  // a PD pull towards a crouch, so the legs move and the contacts change
  JointCommand command;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    command.q_des[i] = (i % 3 == 0) ? 0.0 : (i % 3 == 1 ? 0.9 : -1.6);
    command.kp[i] = 30.0;
    command.kd[i] = 0.6;
  }
  double sensor_difference = 0.0;
  double state_difference = 0.0;
  for (int tick = 0; tick < 600; ++tick) {
    backend.read();
    // the backend's sensors are computed on demand: the start pose has them, later ticks forward
    if (tick > 0) mj_forward(m, d);
    sensor_difference =
        std::max(sensor_difference, largest_difference(d->sensordata, backend.data()->sensordata, m->nsensordata));
    if (tick == 300) {
      // the model changes between a read and the next step: that step must recompute its stages
      for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
        backend.set_foot_friction(leg, 0.3);
        const int geom = mj_name2id(m, mjOBJ_GEOM, (std::string(kLegNames[leg]) + "_foot").c_str());
        m->geom_priority[geom] += 10;
        m->geom_friction[3 * geom] = 0.3;
      }
    }
    backend.write(command);
    for (int step = 0; step < 2; ++step) {
      backend.advance(0.001);
      mju_copy(d->ctrl, backend.data()->ctrl, m->nu);  // the drivers' torques of this step
      mj_step1(m, d);
      mj_step2(m, d);
      state_difference = std::max({state_difference, largest_difference(d->qpos, backend.data()->qpos, m->nq),
                                   largest_difference(d->qvel, backend.data()->qvel, m->nv)});
    }
  }
  // rounding (3.7e-13 and 1.6e-13 measured); a step on the old friction after the change: 0.3
  EXPECT_LT(state_difference, 1e-9);
  EXPECT_LT(sensor_difference, 1e-7);
  // the run did move: the legs left the lying pose
  EXPECT_GT(std::abs(d->qpos[8] - backend.model()->key_qpos[8]), 0.2);
  mj_deleteData(d);
  mj_deleteModel(m);
}

}  // namespace
}  // namespace cerebellum
