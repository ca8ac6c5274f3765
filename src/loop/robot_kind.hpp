// Which robot the MC drives (config robot.kind): its own MuJoCo simulation, or a real robot through
// the low-level interface its vendor offers.
#pragma once

namespace cerebellum {

enum class RobotKind {
  Sim,                // `cerebellum sim`: the simulated CyberDog2, lockstep or paced
  Cyberdog2MotorSdk,  // `cerebellum run`: a CyberDog2 through its motor SDK over LCM, paced by the wall clock
  ZsibotShm,          // `cerebellum run`: a ZsiBot through its daemon's lowlevel.h shared memory, paced likewise
};

// as the configuration writes it, in RobotKind's order
inline constexpr const char* kRobotKindNames[] = {"sim", "cyberdog2_motor_sdk", "zsibot_shm"};
inline const char* robot_kind_name(RobotKind kind) { return kRobotKindNames[static_cast<int>(kind)]; }

}  // namespace cerebellum
