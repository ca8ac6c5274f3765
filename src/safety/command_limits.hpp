// The ranges a joint command must stay in, one struct for every stage that enforces them: the
// guard, the motor SDK's frame rules and the shared-memory frame check.
#pragma once

#include "core/robot_model.hpp"

namespace cerebellum {

struct CommandLimits {
  double kp_max = robot::kCommandKpMax;
  double kd_max = robot::kCommandKdMax;
  double qd_des_max_rad_s = robot::kCommandQdDesMaxRadS;
  double tau_ff_max_nm = robot::kTorqueMaxNm;
  double joint_limit_margin_rad = 0.04;  // q_des kept this far inside the joint range
};

}  // namespace cerebellum
