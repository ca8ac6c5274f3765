// Configuration of the CyberDog2 robot driven through its motor SDK (config section
// `robot.cyberdog2_motor_sdk:`, used when robot.kind is cyberdog2_motor_sdk).
#pragma once

#include <string>

#include "core/robot_model.hpp"
#include "io/lcm_common/lcm_network.hpp"
#include "lowlevel/motor_sdk/motor_sdk_parameters.hpp"

namespace cerebellum {

struct MotorSdkRobotConfig {
  // the robot's motor SDK channels: motor_ctrl out; spi_data and motor_ctrl_state in (control),
  // state_estimator in (estimator). ttl=0 by default: the vendor's MC runs on the same board
  std::string control_url = lcm_url(kLcmMotorSdkPort, 0);
  std::string estimator_url = lcm_url(kLcmStateEstimatorPort, 0);
  // no fresh spi_data or state_estimator for this long: the link is lost and the legs are damped
  double link_timeout_s = 0.020;
  // before the loop starts: all-zero frames until the robot reports motor mode without err_flag
  // bit 1 (the vendor's MC needs the robot to have lain 2 s first)
  double activation_timeout_s = 10.0;
  // what the backend sends, whatever the MC asks, once a motor reports an error (latched until
  // restart, as the vendor's client stops for good)
  double motor_error_damping_kd = robot::kDampingKd;
  // the vendor's command ranges and position-jump steps (8 / 10 / 12 degrees), applied before
  // sending so the robot never has to clamp; position_mutation_limit switches the jump clamp
  MotorSdkParameters rules;
};

}  // namespace cerebellum
