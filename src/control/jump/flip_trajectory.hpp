// A planned flip as the MC plays it: the file that bench/plan_flip writes into config/flips/ and
// the flip mode reads at start (docs/jumps.md, "The flip file"). One CSV row per knot: time,
// phase, the planned trunk (for checks and benchmarks, never for control), then per motor (front
// hip, front knee, rear hip, rear knee; the two legs of a pair alike) the joint target, its rate
// and the feed-forward torque.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cerebellum {

inline constexpr int kFlipMotors = 4;  // front hip, front knee, rear hip, rear knee
inline constexpr int kFlipFilePhases = 3;  // 0 both pairs push, 1 the rear pair pushes, 2 flight

struct FlipSample {
  double time_s;
  int phase;
  std::array<double, 3> trunk;  // planned x (m), z (m), pitch (rad)
  std::array<double, kFlipMotors> q_rad;
  std::array<double, kFlipMotors> qd_rad_s;
  std::array<double, kFlipMotors> tau_nm;
};

struct FlipTrajectory {
  std::vector<FlipSample> samples;
};

// the header line: the column names in their order (their one home)
std::string flip_trajectory_header();

// the file's text: `comment` lines (each written after "# "), the header, one row per sample
std::string flip_trajectory_text(const FlipTrajectory& trajectory, const std::vector<std::string>& comment);

// the trajectory, or nullopt with `error` naming the line and what is wrong: a wrong header or
// column count, a field that is not a finite number, a phase outside 0..2 or going back, time not
// increasing, a joint outside its range (SDK convention), a torque beyond torque_max_nm, fewer than
// two rows
std::optional<FlipTrajectory> parse_flip_trajectory(std::string_view text, double torque_max_nm, std::string& error);
std::optional<FlipTrajectory> read_flip_trajectory(const std::string& path, double torque_max_nm, std::string& error);

}  // namespace cerebellum
