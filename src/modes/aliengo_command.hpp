// What an AlienGo HighCmd asks, in our own types (the wire struct stays in io/udp_aliengo): what
// the AlienGo client's sport session in the tick works with.
#pragma once

#include <array>
#include <cstdint>

namespace cerebellum {

// HighCmd.mode
enum class AlienGoMode : int {
  Idle = 0,
  ForceStand = 1,
  WalkVelocity = 2,
  WalkPosition = 3,
  WalkPath = 4,  // reserved by the vendor: answered "not supported"
  StandDown = 5,
  StandUp = 6,
  Damping = 7,
  Recovery = 8,
};
inline constexpr int kAlienGoModeCount = 9;

// HighCmd.gaitType
enum class AlienGoGait : int { Trot = 0, TrotRunning = 1, Stairs = 2 };

struct AlienGoCommand {
  int mode = 0;
  int gait_type = 0;
  int speed_level = 0;
  float foot_raise_m = 0.0f;        // added to the default swing height
  float body_height_m = 0.0f;       // added to the default body height
  std::array<float, 2> position{};  // mode 3 target, the frame fixed when sport mode started
  std::array<float, 3> rpy{};
  std::array<float, 2> velocity{};  // forward, side (body frame)
  float yaw_speed = 0.0f;
};

}  // namespace cerebellum
