// Configuration of the motor SDK interface (config section `motor_sdk:`).
#pragma once

#include <string>

#include "lowlevel/motor_sdk/motor_sdk_parameters.hpp"

namespace cerebellum {

struct MotorSdkConfig {
  // off by default: an enabled interface opens multicast sockets, which belong in a robot's
  // network or a private network namespace
  bool enabled = false;
  std::string control_url = "udpm://239.255.76.67:7667?ttl=255";    // motor_ctrl, spi_data, ...
  std::string estimator_url = "udpm://239.255.76.67:7669?ttl=255";  // state_estimator
  std::string user_parameter_file;                                  // empty: the rules' defaults
  MotorSdkParameters parameters;  // position_mutation_limit comes from the user parameter file
};

}  // namespace cerebellum
