// The vendor-style user parameter file (cyberdog2-ctrl-user-parameters.yaml). The motor SDK reads
// one key from it, motor_sdk_position_mutation_limit (1 on, 0 off); the file may hold other keys
// for other parts of the MC, which are left alone.
#pragma once

#include <stdexcept>
#include <string>

namespace cerebellum {

struct MotorSdkUserParameters {
  bool position_mutation_limit = true;  // the default when the key is absent
};

class UserParameterError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// throws UserParameterError naming the file, and the key when its value is not 0, 1, true or false
MotorSdkUserParameters load_motor_sdk_user_parameters(const std::string& path);

}  // namespace cerebellum
