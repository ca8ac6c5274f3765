// Configuration of the motor SDK interface (config section `motor_sdk:`).
#pragma once

#include <string>

#include "lowlevel/motor_sdk/motor_sdk_parameters.hpp"
#include "io/lcm_common/lcm_network.hpp"

namespace cerebellum {

struct MotorSdkConfig {
  // served by default on this host only: ttl=0 keeps every packet on the machine (the robot's
  // network takes ttl=255, config/robot-network.yaml)
  bool enabled = true;
  std::string control_url = lcm_url(kLcmMotorSdkPort, 0);          // motor_ctrl, spi_data, ...
  std::string estimator_url = lcm_url(kLcmStateEstimatorPort, 0);  // state_estimator
  std::string user_parameter_file;                                 // empty: the rules' defaults
  MotorSdkParameters parameters;  // position_mutation_limit comes from the user parameter file
};

}  // namespace cerebellum
