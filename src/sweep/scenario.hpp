// A scenario: what one lockstep run of the simulated robot does (the robot's configuration, a
// script of timed high-level commands or the random-command soak, pushes, faults, the seed, how
// long) and the axes a sweep varies. Read from a YAML file by scenario_file.hpp; docs/sweeps.md.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "backend/fault_injecting_backend.hpp"
#include "backend/terrain.hpp"
#include "sweep/model_error_draw.hpp"

namespace cerebellum {

// one high-level command of the script, sent at at_s and kept alive until the next one
struct ScriptedCommand {
  double at_s = 0.0;
  int mode = 0;
  int gait = 0;
  double vx_m_s = 0.0;
  double vy_m_s = 0.0;
  double yaw_rate_rad_s = 0.0;
};

// the random-command soak (the fault soak of bench/): after the script, random gaits and
// velocities held for a random time, a random fault before some of them; after a command the
// robot did not finish walking, the faults are cleared and it is stood up again
struct SoakSpec {
  double start_s = 0.0;  // robot time at which the soak takes over from the script
  std::vector<int> gaits{27, 3, 10, 26, 4, 2, 7, 1};
  double hold_min_s = 1.0;
  double hold_max_s = 3.0;
  double fault_chance = 0.0;  // before each command, the chance of a random fault
  double fault_min_s = 0.3;
  double fault_max_s = 3.0;
};

// a shove of the trunk (the `cerebellum push` disturbance): impulse over length_s, horizontal,
// direction_deg from the robot's start heading (0 front, 90 left)
struct ScenarioPush {
  double at_s = 0.0;
  double impulse_n_s = 0.0;
  double direction_deg = 0.0;
  double length_s = 0.1;
};

struct Scenario {
  std::string file;         // where it was read, for messages
  std::string config_path;  // the MC's configuration file (absolute or relative to the cwd); empty: defaults
  bool sensor_noise = false;  // the simulated sensors' noise, seeded by the run's seed
  // the robot's differences from the model, drawn per run from the run's seed; unset: exact
  std::optional<ModelErrorRanges> model_error;
  // the ground of every run (docs/terrain.md); unset: the configuration's robot.terrain
  std::optional<TerrainSpec> terrain;
  unsigned seed = 1;          // the noise and the soak's draws
  double duration_s = 10.0;   // robot time of a run
  // > 0: the run ends this long after the last push has ended (duration_s is then unused)
  double end_after_last_push_s = 0.0;
  std::vector<ScriptedCommand> commands;
  std::optional<SoakSpec> soak;
  std::vector<ScenarioPush> pushes;
  std::vector<TimedFault> faults;
  // a run that ends moving faster than this (m/s, the trunk's horizontal speed) is judged
  // "moving"; 0: not judged
  double settle_speed_m_s = 0.0;
};

// what a sweep may vary, each a key of the file's `sweep:` mapping
// JumpOrMotionId: the gait_id of every jump (16) and named motion (62) command of the script
enum class AxisKind { Seed, Gait, PushImpulse, PushDirection, PushAt, Terrain, JumpOrMotionId };
struct Axis {
  AxisKind kind = AxisKind::Seed;
  std::string name;  // as the file writes it: seed, gait, push_impulse_n_s, push_direction_deg, push_at_s, terrain,
                     // jump_or_motion_id
  std::vector<double> values;  // terrain: the indices of terrains, so the grid counts every axis alike
  std::vector<TerrainSpec> terrains;  // terrain: the grounds, in the file's order
};

struct SweepSpec {
  Scenario base;
  std::vector<Axis> axes;  // in the file's order; the last varies fastest
};

// the axes' names as the file writes them, for messages and the results' columns
const std::array<const char*, 7>& axis_names();

}  // namespace cerebellum
