// Push sweep: which shoves the robot survives, trotting in place (11/3) and in the two stands (11/1
// with push recovery, 11/31 without), over impulses, four directions and five moments of the trot
// cycle. The push is the `cerebellum push` disturbance (Simulation::request_force_pulse on the
// trunk, 0.1 s unless --push_s says otherwise); control runs on the robot's own estimate, the
// simulator's truth only scores. A run survives when the trunk never tilts past 34 degrees, the
// robot is still in mode 11 (not damped by a protective stop) and, 3 s after the push, moves
// slower than 0.3 m/s; falls and stops are counted apart. Prints a markdown table
// (docs/benchmarks.md).
//   push_sweep_bench [--impulses=5,10,15,20,25,30] [--phases=5] [--push_s=0.1] [--gaits=3,1,31] [--offset_s=0]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "loop/lockstep_client.hpp"
#include "loop/simulated_robot.hpp"
#include "control/locomotion/gait.hpp"
#include "control/locomotion/gait_table.hpp"
#include "sweep/random_soak.hpp"

namespace {

using namespace cerebellum;

constexpr double kSettleAfterPushS = 3.0;

struct Behaviour {
  const char* name;
  int gait_id;
};

// Stopped: upright but no longer walking (a protective stop damped the joints: it sits down)
enum class Outcome { Survived, StillMoving, Stopped, Fell };

// one run: stand up, take the gait for 2 s plus the phase offset, push, watch 3 s
Outcome push_outcome(int gait_id, double impulse_n_s, double push_s, const std::array<double, 2>& direction,
                     double offset_s) {
  McConfig config = default_config();
  config.startup = Startup::Off;
  config.robot.model_path = std::string(CEREBELLUM_MODEL_DIR) + "/cyberdog2.xml";
  Mc mc = make_simulated_mc(config);
  LockstepClient client(mc);
  client.run(high_level_command(ModeId::RecoveryStand, 0), 3.0);
  const HighLevelCommand gait = high_level_command(ModeId::Locomotion, gait_id);
  client.run(gait, 2.0 + offset_s);
  const double force_n = impulse_n_s / push_s;
  mc.simulation().request_force_pulse({{force_n * direction[0], force_n * direction[1], 0.0}, push_s});
  bool up = true;
  client.run(gait, push_s + kSettleAfterPushS,
             [&](const CycleRecord&) { up &= upright(mc.simulation().ground_truth()); });
  const auto v = mc.simulation().ground_truth().velocity_world;
  if (!up) return Outcome::Fell;
  if (mc.machine().status().mode != static_cast<int>(ModeId::Locomotion)) return Outcome::Stopped;
  return std::hypot(v[0], v[1]) < 0.3 ? Outcome::Survived : Outcome::StillMoving;
}

std::vector<double> numbers(const std::string& text) {
  std::vector<double> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) out.push_back(std::stod(item));
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<double> impulses{5, 10, 15, 20, 25, 30};
  int phases = 5;
  double push_s = 0.1;
  double offset_s = 0.0;
  std::vector<double> gaits{3, kStandGaitId, kStandWithoutPushRecoveryGaitId};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--impulses=", 0) == 0) impulses = numbers(arg.substr(11));
    if (arg.rfind("--phases=", 0) == 0) phases = std::stoi(arg.substr(9));
    if (arg.rfind("--push_s=", 0) == 0) push_s = std::stod(arg.substr(9));
    if (arg.rfind("--gaits=", 0) == 0) gaits = numbers(arg.substr(8));
    // shifts every moment of the cycle: a fresh set of moments for figures no tuning looked at
    if (arg.rfind("--offset_s=", 0) == 0) offset_s = std::stod(arg.substr(11));
  }
  const Behaviour behaviours[] = {{"trot in place (11/3)", 3},
                                  {"stand with push recovery (11/1)", kStandGaitId},
                                  {"stand without push recovery (11/31)", kStandWithoutPushRecoveryGaitId}};
  const struct {
    const char* name;
    std::array<double, 2> direction;
  } directions[] = {{"left", {0, 1}}, {"right", {0, -1}}, {"front", {1, 0}}, {"back", {-1, 0}}};
  const double trot_cycle_s = gait_pattern(3)->period_segments * kGaitSegmentS;

  std::printf("| behaviour | direction |");
  for (double impulse : impulses) std::printf(" %.0f N s |", impulse);
  std::printf("\n|---|---|");
  for (std::size_t k = 0; k < impulses.size(); ++k) std::printf("---|");
  std::printf("\n");
  for (const Behaviour& behaviour : behaviours) {
    if (std::find(gaits.begin(), gaits.end(), behaviour.gait_id) == gaits.end()) continue;
    for (const auto& direction : directions) {
      std::printf("| %s | %s |", behaviour.name, direction.name);
      for (double impulse : impulses) {
        int survived = 0;
        int fell = 0;
        int stopped = 0;
        for (int phase = 0; phase < phases; ++phase) {
          const Outcome outcome = push_outcome(behaviour.gait_id, impulse, push_s, direction.direction,
                                               offset_s + trot_cycle_s * phase / phases);
          survived += outcome == Outcome::Survived;
          fell += outcome == Outcome::Fell;
          stopped += outcome == Outcome::Stopped;
        }
        std::printf(" %d/%d", survived, phases);
        if (fell > 0 && stopped > 0) {
          std::printf(" (%d fell, %d stopped)", fell, stopped);
        } else if (fell > 0) {
          std::printf(" (%d fell)", fell);
        } else if (stopped > 0) {
          std::printf(" (%d stopped)", stopped);
        }
        std::printf(" |");
        std::fflush(stdout);
      }
      std::printf("\n");
    }
  }
  std::printf(
      "\nsurvived / runs per cell (%d moments of the %.2f s trot cycle from %.3f s), pushes of %.2f s; a run that did "
      "not fall but "
      "still moved faster than 0.3 m/s 3 s after the push, or ended in a protective stop (stopped: the joints damped, "
      "out of mode 11), is not counted as survived\n",
      phases, trot_cycle_s, offset_s, push_s);
  return 0;
}
