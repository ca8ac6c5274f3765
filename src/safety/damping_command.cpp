#include "safety/damping_command.hpp"

namespace cerebellum {

JointCommand damping_command(double kd, const JointArray<double>& q_des) {
  JointCommand command;
  command.q_des = q_des;
  command.kd.fill(kd);
  return command;
}

}  // namespace cerebellum
