#include "lowlevel/motor_sdk/motor_sdk_user_parameters.hpp"

#include <yaml-cpp/yaml.h>

#include <filesystem>

namespace cerebellum {

MotorSdkUserParameters load_motor_sdk_user_parameters(const std::string& path) {
  static constexpr const char* kKey = "motor_sdk_position_mutation_limit";
  if (!std::filesystem::is_regular_file(path)) throw UserParameterError("user parameter file not found: " + path);
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw UserParameterError("user parameter file " + path + ": not valid YAML: " + e.what());
  }
  MotorSdkUserParameters parameters;
  if (root.IsNull()) return parameters;
  if (!root.IsMap()) throw UserParameterError("user parameter file " + path + ": must be a mapping of keys");
  const YAML::Node value = root[kKey];
  if (!value) return parameters;
  const std::string text = value.IsScalar() ? value.Scalar() : std::string("<not a scalar>");
  if (text == "1" || text == "true") {
    parameters.position_mutation_limit = true;
  } else if (text == "0" || text == "false") {
    parameters.position_mutation_limit = false;
  } else {
    throw UserParameterError("user parameter file " + path + ": " + kKey + " must be 0 or 1, got '" + text + "'");
  }
  return parameters;
}

}  // namespace cerebellum
