// The flips (16/20 back, 16/21 front) through the whole MC over seeded runs with sensor noise,
// judged on the simulator's truth: pitch turned (the trunk's pitch rate integrated from the command
// on), the distance from the take-off to where it stands, the peak motor torque, the hottest
// winding's rise, falls (tilt past 1 rad or trunk below 0.1 m once the landing has begun, or
// damped) and runs that stood (the response at 100 and the trunk above 0.2 m, level within 0.1 rad).
//   flip_bench [--flip=back|front] [--seeds=A-B]
// Without --flip: both flips, each on its own fresh seeds (the back flip 501-520, the front flip
// 601-620: seeds no tuning decision looked at); --seeds replaces them. Arguments of Google
// Benchmark's (--benchmark_*, which bench/run.sh passes to every benchmark) are ignored.
#include <cstdio>
#include <string>
#include <vector>

#include "modes/jump_mode.hpp"
#include "soak_support.hpp"
#include "sweep/flip_trial.hpp"

namespace {

struct FlipSeeds {
  const char* name;
  int gait_id;
  long first;
  long last;
};

// one table; true when every run stood and none fell
bool run_flip(const FlipSeeds& f) {
  std::printf("%s flip (16/%d), seeds %ld-%ld\n\n", f.name, f.gait_id, f.first, f.last);
  std::printf("| seed | turned (rad) | distance from take-off (m) | peak torque (Nm) | temperature rise (deg C) | fell | stood |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  int stood = 0, fell = 0;
  for (long seed = f.first; seed <= f.last; ++seed) {
    const cerebellum::FlipTrial t = cerebellum::run_flip_trial(cerebellum::bench::soak_config(seed), f.gait_id);
    stood += t.stood ? 1 : 0;
    fell += t.fell ? 1 : 0;
    std::printf("| %ld | %.4f | %.4f | %.2f | %.3f | %s | %s |\n", seed, t.turned_rad, t.distance_m, t.peak_torque_nm,
                t.temperature_rise_c, t.fell ? "yes" : "no", t.stood ? "yes" : "no");
    std::fflush(stdout);
  }
  const long runs = f.last - f.first + 1;
  std::printf("%s flip: stood %d of %ld, fell %d\n\n", f.name, stood, runs, fell);
  return stood == runs && fell == 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<FlipSeeds> flips{{"back", cerebellum::kBackFlipGaitId, 501, 520},
                               {"front", cerebellum::kFrontFlipGaitId, 601, 620}};
  std::string only;
  long first = -1, last = -1;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--benchmark_", 0) == 0) continue;
    if (arg.rfind("--seeds=", 0) == 0 && std::sscanf(arg.c_str() + 8, "%ld-%ld", &first, &last) == 2 && first <= last) continue;
    if (arg == "--flip=back" || arg == "--flip=front") {
      only = arg.substr(7);
      continue;
    }
    std::fprintf(stderr, "usage: flip_bench [--flip=back|front] [--seeds=A-B]\n");
    return 2;
  }
  bool all_stood = true;
  for (FlipSeeds f : flips) {
    if (!only.empty() && only != f.name) continue;
    if (first >= 0) f.first = first, f.last = last;
    all_stood &= run_flip(f);
  }
  return all_stood ? 0 : 1;
}
