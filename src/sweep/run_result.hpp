// What one run of a scenario measured, and its verdict. Every field comes from robot time and
// the simulator's truth, never the wall clock, so the same cell gives the same result anywhere.
#pragma once

#include <string>
#include <vector>

namespace cerebellum {

struct RunResult {
  // ok | fell | stopped | moving | unsafe (see judge_run); crashed is given by the sweep to a
  // worker that ended without a result
  std::string outcome = "ok";
  double robot_time_s = 0.0;
  long long ticks = 0;
  int commands = 0;  // high-level commands sent (script and soak)
  int faults = 0;    // faults injected (scenario and soak)
  int pushes = 0;
  int falls = 0;               // the trunk tipped past 0.6 rad from upright, after being upright
  double first_fall_s = -1.0;  // -1: none
  int falls_no_fault_near = 0;  // a fall more than 5 s after every fault had ended
  int falls_not_safe = 0;       // a fall not followed within 3 s by damped or off motors, or upright again
  int protections = 0;          // the health protection started
  long long non_finite_commands = 0;  // commands to the motors with a NaN or infinity
  double max_tilt_deg = 0.0;
  double end_speed_m_s = 0.0;   // the trunk's horizontal speed at the end
  int end_mode = 0;             // the high-level mode at the end
  double distance_m = 0.0;      // the trunk's horizontal displacement, start to end
  // a soak's falls, one line each with the commands before it, for the run's log (not a column)
  std::vector<std::string> fall_notes;
};

}  // namespace cerebellum
