// What a real robot's low-level interface reports, each part as it arrives on its own (the joints
// in one message, the IMU in another), before a link watch makes a SensorFrame of them
// (io/robot_link/robot_state_watch.hpp). SDK joint convention.
#pragma once

#include <array>
#include <cstdint>

#include "core/types.hpp"

namespace cerebellum {

struct JointReading {
  JointArray<double> q{};
  JointArray<double> qd{};
  JointArray<double> tau{};
  JointArray<double> temperature_c{};
  JointArray<std::uint32_t> motor_faults{};
  JointArray<MotorDriverMode> driver_mode = all_motor_mode();
};

struct ImuReading {
  std::array<double, 4> quat{1.0, 0.0, 0.0, 0.0};  // w, x, y, z, body to world
  std::array<double, 3> gyro_rad_s{};              // body frame
  std::array<double, 3> specific_force_m_s2{};     // body frame, +9.81 on z at rest
};

// how the link to a real robot fares, as its backend sees it at one tick (a simulation has none)
struct RobotLinkReport {
  bool present = false;
  double state_age_s = 0.0;             // how old the newest full state (joints and IMU) was when read
  std::uint64_t losses = 0;             // since start: times the link was lost
  std::uint64_t states_refused = 0;     // since start: states that repeated the one before or jumped
  std::uint64_t frames_late = 0;        // since start: frames the robot reported late or left a cycle untaken
  // where the link shows when the robot took a frame (the ZsiBot's flags): from writing a frame to
  // the first state the robot published after taking it, the newest one measured, and how many so
  // far (0: the link cannot tell, as the motor SDK, which echoes nothing)
  double round_trip_s = 0.0;
  std::uint64_t round_trips = 0;
};

}  // namespace cerebellum
