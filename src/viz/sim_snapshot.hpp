// What the tools draw and log of one control tick: a copy of the simulator's state plus the MC's
// status, taken in the loop thread and handed to a viewer, recorder or logger thread.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/high_level_command.hpp"

namespace cerebellum {

struct SimSnapshot {
  std::uint64_t tick = 0;
  double time_s = 0.0;
  std::vector<double> qpos;                  // sized to the model's nq once, then copied into
  std::vector<double> qvel;                  // sized to the model's nv
  std::array<double, 3> external_force_n{};  // the push on the trunk (world frame)
  HighLevelStatus status;
  std::array<double, 3> commanded_velocity{};  // vx, vy (m/s), yaw rate (rad/s) asked of mode 11
  // the estimator's view
  std::array<double, 3> estimated_velocity_body{};  // vx, vy (m/s), yaw rate (rad/s)
  double estimated_height_m = 0.0;
  // simulator truth, labelled as such wherever shown
  std::array<double, 3> true_velocity_body{};  // vx, vy (m/s), yaw rate (rad/s)
  double true_height_m = 0.0;
  // the robot's health: battery (state of charge < 0 without one), the hottest motor, and the
  // motors reporting an error or a warning (bit i: motor i)
  double battery_soc_percent = -1.0;
  double battery_v = 0.0;
  double hottest_motor_c = 0.0;
  int hottest_motor = 0;
  std::uint32_t faulty_motors = 0;
};

}  // namespace cerebellum
