// Configuration of the ZsiBot driven through its daemon's lowlevel.h shared memory (config section
// `robot.zsibot_shm:`, used when robot.kind is zsibot_shm).
#pragma once

#include <string>

#include "core/robot_model.hpp"

namespace cerebellum {

struct ShmRobotConfig {
  // the daemon's objects are "/" + name_prefix + "spline_shm" and "/" + name_prefix + "imu_shm":
  // empty on a robot (the vendor's names); a prefix reaches a daemon that serves others, as the
  // stacked pair's MC A does
  std::string name_prefix;
  // no fresh joint state or IMU for this long: the link is lost and the legs are damped
  double link_timeout_s = 0.020;
  // before the loop starts: until the daemon's objects exist and its state is updating
  double activation_timeout_s = 10.0;
  // what the MC sends, whatever it would command, once a motor reports an error (latched until
  // restart, as the CyberDog2's client does)
  double motor_error_damping_kd = robot::kDampingKd;
};

}  // namespace cerebellum
