// A soak of random commands with random faults injected (docs/safety.md): the whole MC in
// lockstep on the simulated robot with sensor noise, random gaits and velocities held 1-3 s, and
// before about every third command a random fault of random length (0.3-3 s) from the fault
// grammar. Checked on every tick: the command written to the motors is finite. Checked on the
// truth after each command: a fall (the trunk tipped past 0.6 rad from upright) must come within
// 5 s of a fault, and within 3 s of it the motors must be damped or off (or the robot up again).
// Prints a table of the counts per fault kind and the falls.
//   fault_soak_bench [--minutes=M] [--seed=N] [--verbose]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "loop/lockstep_client.hpp"
#include "loop/simulated_robot.hpp"
#include "safety/command_finite.hpp"
#include "soak_support.hpp"
#include "sweep/run_watch.hpp"

namespace {

using namespace cerebellum;

using bench::upright;

}  // namespace

int main(int argc, char** argv) {
  double minutes = 10.0;
  unsigned seed = 1;
  bool verbose = false;  // every fault and command on stderr
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--verbose") verbose = true;
    if (arg.rfind("--minutes=", 0) == 0) minutes = std::stod(arg.substr(10));
    if (arg.rfind("--seed=", 0) == 0) seed = static_cast<unsigned>(std::stoul(arg.substr(7)));
  }
  Mc mc = make_simulated_mc(bench::soak_config(seed));
  LockstepClient client(mc);
  std::mt19937 rng(seed);
  const std::vector<int> gaits{27, 3, 10, 26, 4, 2, 7, 1};
  std::uniform_real_distribution<double> hold(1.0, 3.0), fault_length(0.3, 3.0), chance(0.0, 1.0);

  client.run(high_level_command(ModeId::RecoveryStand, 0), 3.0);
  std::map<std::string, int> injected;
  int commands = 0, falls = 0, unexplained = 0, unsafe = 0, protections = 0, recovered = 0;
  long long ticks = 0, non_finite = 0;
  double last_fault_end_s = -1e9;
  bool was_protecting = false;
  const auto each_tick = [&](const CycleRecord& record) {
    ++ticks;
    if (!command_is_finite(record.command)) ++non_finite;
    if (record.health.protecting() && !was_protecting) {
      ++protections;
      if (verbose) {
        std::fprintf(stderr, "%.2f s: protection, causes 0x%02x\n", record.state.time_s,
                     static_cast<unsigned>(record.health.causes));
      }
    }
    was_protecting = record.health.protecting();
  };
  const double end = mc.backend().time_s() + 60.0 * minutes;
  while (mc.backend().time_s() < end) {
    if (chance(rng) < 0.35) {
      const std::string fault = cerebellum::random_fault(rng);
      const double length_s = fault_length(rng);
      std::string text = fault;
      text += " for ";
      text += std::to_string(length_s);
      const FaultParse parsed = parse_fault(text);
      if (!parsed.request || !mc.faults()->request(*parsed.request).empty()) {
        std::fprintf(stderr, "fault_soak: the bench's own fault was refused: %s: %s\n", fault.c_str(),
                     parsed.error.c_str());
        return 1;
      }
      ++injected[fault_kind_name(fault)];
      if (verbose) std::fprintf(stderr, "%.2f s: fault %s\n", mc.backend().time_s(), text.c_str());
      last_fault_end_s = std::max(last_fault_end_s, mc.backend().time_s() + length_s);
    }
    const bench::WalkCommand walk = bench::random_walk_command(rng, gaits);
    const int gait = walk.gait;
    const Eigen::Vector3d& v = walk.velocity;
    ++commands;
    if (verbose) {
      std::fprintf(stderr, "%.2f s: gait %d v (%.2f, %.2f, %.2f), status mode %d switch %d\n", mc.backend().time_s(),
                   gait, v.x(), v.y(), v.z(), mc.machine().status().mode,
                   static_cast<int>(mc.machine().status().switch_status));
    }
    bool up = true;
    double fell_at_s = -1.0;
    client.run(high_level_command(ModeId::Locomotion, gait, v.x(), v.y(), v.z()), hold(rng),
               [&](const CycleRecord& record) {
                 each_tick(record);
                 if (up && !upright(mc.simulation().ground_truth())) {
                   up = false;
                   fell_at_s = mc.backend().time_s();
                 }
               });
    const HighLevelStatus& status = mc.machine().status();
    const bool walking = status.mode == static_cast<int>(ModeId::Locomotion) && status.gait_id == gait;
    if (up && walking) continue;
    if (!up) {
      ++falls;
      const bool explained = fell_at_s <= last_fault_end_s + 5.0;
      unexplained += !explained;
      // safe within 3 s of the fall: motors damped or off, or the robot up again
      bool safe = false;
      const double deadline = fell_at_s + 3.0;
      while (mc.backend().time_s() < deadline && !safe) {
        each_tick(mc.loop().tick());
        safe = damped_or_off(mc.loop().last_cycle().command) || upright(mc.simulation().ground_truth());
      }
      safe |= damped_or_off(mc.loop().last_cycle().command) || upright(mc.simulation().ground_truth());
      unsafe += !safe;
      std::fprintf(stderr, "fault_soak: fall at %.1f s (%s, %s) after gait %d v (%.2f, %.2f, %.2f)\n", fell_at_s,
                   explained ? "a fault within 5 s" : "NO FAULT NEAR", safe ? "safe" : "NOT SAFE", gait, v.x(), v.y(),
                   v.z());
    }
    // stood up again once the faults are over (the protection ignores commands until it has
    // ended, 0.5 s after its last cause)
    mc.faults()->request(parse_fault("clear").request.value());
    client.run(high_level_command(ModeId::PureDamper, 0), 0.6, each_tick);
    client.run(high_level_command(ModeId::RecoveryStand, 0), 8.0, each_tick);
    recovered += upright(mc.simulation().ground_truth()) && mc.machine().status().order_process_bar >= 95;
  }

  std::printf("fault soak: %.0f min of robot time, seed %u, sensor noise on\n\n", minutes, seed);
  std::printf("| fault | injected |\n|---|---|\n");
  int total = 0;
  for (const auto& [kind, count] : injected) {
    std::printf("| %s | %d |\n", kind.c_str(), count);
    total += count;
  }
  std::printf("| all | %d |\n\n", total);
  std::printf(
      "| commands | ticks | non-finite commands | protections | falls | falls with no fault near | "
      "falls not made safe | stand-ups after a stop or fall |\n|---|---|---|---|---|---|---|---|\n");
  std::printf("| %d | %lld | %lld | %d | %d | %d | %d | %d |\n", commands, ticks, non_finite, protections, falls,
              unexplained, unsafe, recovered);
  return non_finite == 0 && unexplained == 0 && unsafe == 0 ? 0 : 1;
}
