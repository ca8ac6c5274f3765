#include "control/passive_controller.hpp"

namespace cerebellum {

void PassiveController::compute(const RobotState& state, JointCommand& command) {
  command = JointCommand{};
  command.kd.fill(damping_kd_);
  command.q_des = state.q;
}

}  // namespace cerebellum
