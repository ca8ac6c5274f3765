// Mode 21 in simulation: position-based pose control reaches its poses, gait 5 its height, gait 2
// lifts a leg (hand shake) while the body stays up.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "modes/mode_sim.hpp"

namespace cerebellum {
namespace {

using testing::command;
using testing::ModeSim;

HighLevelCommand pose(double roll, double pitch, double yaw, double dz = 0.0, int gait = 0) {
  HighLevelCommand c = command(ModeId::PoseControl, gait);
  c.rpy_des = {static_cast<float>(roll), static_cast<float>(pitch), static_cast<float>(yaw)};
  c.pos_des = {0.0f, 0.0f, static_cast<float>(dz)};
  return c;
}

TEST(PoseControlSim, Debug) {
  const double R = std::getenv("R") ? std::atof(std::getenv("R")) : 0.0;
  const double P = std::getenv("P") ? std::atof(std::getenv("P")) : 0.0;
  const double Y = std::getenv("Y") ? std::atof(std::getenv("Y")) : 0.0;
  const double Z = std::getenv("Z") ? std::atof(std::getenv("Z")) : 0.0;
  ModeSim sim;
  sim.run(3.0);
  const double yaw0 = sim.true_rpy().z();
  sim.send(pose(0, 0, 0), 1.5);
  for (int i = 0; i < 25; ++i) {
    const Eigen::Vector3d rpy = sim.true_rpy();
    std::printf("t %.2f h %.3f rpy %.3f %.3f %.3f bar %d\n", sim.time_s(), sim.true_height(), rpy.x(), rpy.y(), rpy.z() - yaw0,
                sim.status().order_process_bar);
    if (i == 0) sim.send(pose(R, P, Y, Z), 0.1); else sim.run(0.1);
  }
}

}  // namespace
}  // namespace cerebellum
namespace cerebellum {
TEST(PoseControlSim, ShakeDebug) {
  testing::ModeSim sim;
  sim.run(3.0);
  HighLevelCommand c = testing::command(ModeId::PoseControl, 2);
  c.contact = 0b1110;
  c.foot_pose = {0.08f, 0.0f, 0.12f, 0, 0, 0};
  for (int i = 0; i < 40; ++i) {
    const Eigen::Vector3d rpy = sim.true_rpy();
    std::printf("t %.2f h %.3f rpy %.3f %.3f foot %.3f %.3f bar %d mode %d\n", sim.time_s(), sim.true_height(), rpy.x(), rpy.y(),
                sim.true_foot(0).x(), sim.true_foot(0).z(), sim.status().order_process_bar, sim.status().mode);
    if (i == 0) sim.send(c, 0.1); else if (i == 25) { c.gait_id = 0; c.contact = 0x0F; sim.send(c, 0.1);} else sim.run(0.1);
  }
}
}
