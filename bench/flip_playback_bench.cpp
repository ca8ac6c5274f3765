// The shipped flip file played open loop on the simulated robot, per seed (bench/flip_playback_run):
//   flip_playback_bench [--file PATH] [--seeds A-B] [--trace-every-s S] [--kp X] [--kd Y]   (default
//   config/flips/back_flip.csv, seeds 0-0; --trace-every-s prints the trunk against the plan)
// Seed 0 is the plan's own start; others perturb the start and the feet's friction. One row per
// seed and a summary: rotation, flight, peak torque, temperature rise, landing distance, landed upright.
#include <cstdio>
#include <string>

#include "control/jump/flip_trajectory.hpp"
#include "core/number_text.hpp"
#include "core/robot_model.hpp"
#include "flip_playback_run.hpp"

int main(int argc, char** argv) {
  using namespace cerebellum;
  std::string path = std::string(CEREBELLUM_MODEL_DIR) + "/../config/flips/back_flip.csv";
  long first = 0, last = 0;
  double trace_every_s = 0.0;
  FlipPlayGains gains;  // the player's own unless asked (an experiment: the MC plays with its defaults)
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    // Google Benchmark's arguments, which bench/run.sh passes to every benchmark
    if (option.rfind("--benchmark_", 0) == 0) continue;
    const std::string value = i + 1 < argc ? argv[++i] : "";
    if (value.empty()) {
      std::fprintf(stderr, "flip_playback_bench: %s needs a value\n", option.c_str());
      return 2;
    } else if (option == "--file") {
      path = value;
    } else if (option == "--seeds" && std::sscanf(value.c_str(), "%ld-%ld", &first, &last) == 2 && first <= last) {
    } else if (option == "--trace-every-s" && std::sscanf(value.c_str(), "%lf", &trace_every_s) == 1 && trace_every_s > 0.0) {
    } else if (option == "--kp" && std::sscanf(value.c_str(), "%lf", &gains.kp) == 1 && gains.kp >= 0.0) {
    } else if (option == "--kd" && std::sscanf(value.c_str(), "%lf", &gains.kd) == 1 && gains.kd >= 0.0) {
    } else {
      std::fprintf(stderr, "usage: flip_playback_bench [--file PATH] [--seeds A-B] [--trace-every-s S] [--kp X] [--kd Y]\n");
      return 2;
    }
  }
  std::string error;
  const auto trajectory = read_flip_trajectory(path, robot::kTorqueMaxNm, error);
  if (!trajectory) {
    std::fprintf(stderr, "flip_playback_bench: %s\n", error.c_str());
    return 1;
  }
  std::printf("| seed | turned at the plan's end (rad) | turned in all (rad) | flight (s) | peak torque (Nm) | rear knee (Nm) | temperature rise (deg C) | landing distance (m) | landed upright |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  int upright = 0;
  for (long seed = first; seed <= last; ++seed) {
    FlipPlaybackSetup setup;
    setup.model_path = std::string(CEREBELLUM_MODEL_DIR) + "/cyberdog2.xml";
    setup.seed = static_cast<std::uint64_t>(seed);
    setup.trace_every_s = trace_every_s;
    setup.gains = gains;
    const FlipPlaybackOutcome o = play_flip_on_simulation(*trajectory, setup);
    upright += o.landed_upright ? 1 : 0;
    std::printf("| %ld | %.2f | %.2f | %.3f | %.1f | %.1f | %.2f | %.2f | %s |\n", seed, o.pitch_at_plan_end_rad, o.pitch_turned_rad,
                o.flight_s, o.peak_torque_nm, o.peak_rear_knee_nm, o.temperature_rise_c, o.landing_distance_m, o.landed_upright ? "yes" : "no");
  }
  std::printf("landed upright: %d of %ld\n", upright, last - first + 1);
  return 0;
}
