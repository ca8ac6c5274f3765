// Mode 3 in simulation: the force-based stand reaches its pose targets and balances on three legs.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "modes/mode_sim.hpp"

namespace cerebellum {
namespace {

using testing::command;
using testing::ModeSim;

HighLevelCommand qp_pose(double roll, double pitch, double yaw, double height) {
  HighLevelCommand c = command(ModeId::QpStand, 0);
  c.rpy_des = {static_cast<float>(roll), static_cast<float>(pitch), static_cast<float>(yaw)};
  c.pos_des = {0.0f, 0.0f, static_cast<float>(height)};
  return c;
}

TEST(QpStandSim, ReachesRollPitchYawAndHeight) {
  const double R = std::getenv("R") ? std::atof(std::getenv("R")) : 0.0;
  const double P = std::getenv("P") ? std::atof(std::getenv("P")) : 0.0;
  const double Y = std::getenv("Y") ? std::atof(std::getenv("Y")) : 0.0;
  const double H = std::getenv("H") ? std::atof(std::getenv("H")) : 0.235;
  ModeSim sim;
  sim.run(3.0);
  ASSERT_EQ(sim.status().order_process_bar, 100);
  const double yaw0 = sim.true_rpy().z();
  sim.send(qp_pose(0.0, 0.0, 0.0, 0.235), 1.5);
  for (int i = 0; i < 30; ++i) {
    const Eigen::Vector3d rpy = sim.true_rpy();
    const auto& ctl = sim.qp_stand.stand().controller();
    Eigen::Vector3d fsum = Eigen::Vector3d::Zero();
    for (const auto& f : ctl.foot_forces()) fsum += f;
    std::printf("t %.2f h %.3f est %.3f rpy %.3f %.3f %.3f bar %d ok %d w %.1f %.1f %.1f | %.2f %.2f %.2f fz %.1f\n", sim.time_s(), sim.true_height(),
                ctl.estimated_pose().position.z(), rpy.x(), rpy.y(), rpy.z() - yaw0,
                sim.status().order_process_bar, ctl.last_solve_ok(), ctl.demanded_wrench()(0), ctl.demanded_wrench()(1), ctl.demanded_wrench()(2),
                ctl.demanded_wrench()(3), ctl.demanded_wrench()(4), ctl.demanded_wrench()(5), fsum.z());
    if (i == 0) sim.send(qp_pose(R, P, Y, H), 0.1); else sim.run(0.1);
  }
  const Eigen::Vector3d rpy = sim.true_rpy();
  EXPECT_NEAR(rpy.x(), R, 0.03);
  EXPECT_NEAR(rpy.y(), P, 0.03);
  EXPECT_NEAR(rpy.z() - yaw0, Y, 0.03);
  EXPECT_NEAR(sim.true_height(), H, 0.01);
}

}  // namespace
}  // namespace cerebellum
namespace cerebellum {
TEST(QpStandSim, PrintCom) {
  testing::ModeSim sim;
  sim.run(3.0);
  const mjData* d = sim.backend.data();
  const mjModel* m = sim.backend.model();
  const int trunk = mj_name2id(m, mjOBJ_BODY, "trunk");
  Eigen::Vector3d com(d->subtree_com[3 * trunk], d->subtree_com[3 * trunk + 1], d->subtree_com[3 * trunk + 2]);
  Eigen::Vector3d pos(d->xpos[3 * trunk], d->xpos[3 * trunk + 1], d->xpos[3 * trunk + 2]);
  const Eigen::Vector3d body = sim.true_orientation().toRotationMatrix().transpose() * (com - pos);
  std::printf("com in body %.4f %.4f %.4f mass %.4f\n", body.x(), body.y(), body.z(), m->body_subtreemass[trunk]);
  for (int i = 0; i < 12; ++i) std::printf("%.3f ", sim.state().q[i]);
  std::printf("\n");
}
}
namespace cerebellum {
TEST(QpStandSim, LiftDebug) {
  testing::ModeSim sim;
  sim.run(3.0);
  const int leg = std::getenv("LEG") ? std::atoi(std::getenv("LEG")) : 0;
  HighLevelCommand c = testing::command(ModeId::QpStand, 0);
  c.contact = 0x0F & ~(1 << leg);
  for (int i = 0; i < 40; ++i) {
    const Eigen::Vector3d rpy = sim.true_rpy();
    const auto& st = sim.qp_stand.stand();
    std::printf("t %.2f h %.3f rpy %.3f %.3f foot %.3f  bar %d ok %d phase sh %.2f ld %.2f lf %.2f f %.1f %.1f %.1f %.1f\n", sim.time_s(), sim.true_height(), rpy.x(), rpy.y(),
                sim.true_foot(leg).z(), sim.status().order_process_bar, st.controller().last_solve_ok(), st.support().shift(), st.support().load(), st.support().lift(),
                st.controller().foot_forces()[0].z(), st.controller().foot_forces()[1].z(), st.controller().foot_forces()[2].z(), st.controller().foot_forces()[3].z());
    if (i == 0) sim.send(c, 0.1); else if (i == 25) { c.contact = 0x0F; sim.send(c, 0.1);} else sim.run(0.1);
  }
}
}
