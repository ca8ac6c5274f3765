// The flip planner as a tool: plans a flip of the planar model (src/control/flip_plan)
// with IPOPT and writes it as a flip file (src/control/jump/flip_trajectory.hpp).
//   plan_flip [--torque-max-nm X] [--turn-rad R] [--iterations N] [--intervals A,B,C] [--stance-force-min-n F]
//             [--landing-distance-max-m D] [--phase-max-s A,B,C] [--last-pair front|rear] [--out PATH]
// (the shipped back flip: the defaults; the shipped front flip: --last-pair front
// --landing-distance-max-m 0, docs/jumps.md says why; --last-pair front turns +2 pi unless
// --turn-rad says otherwise)
// (--landing-distance-max-m: the trunk's touchdown within this of its start, along the body, default 0.5)
// (--phase-max-s: the phases' longest durations, default 0.4,0.25,0.8)
// (--intervals: the collocation intervals of the three phases, default 20,14,26)
// --turn-rad 0 asks the largest back turn the limits allow instead of a full turn. Prints the
// solver's status, the turn, the peak torques, the phases' durations and the model's residual.
// Raising --torque-max-nm is an experiment (what limit would a flip need); the shipped file is
// planned with the motors' own 12 Nm.
#include <cstdio>
#include <fstream>
#include <string>

#include "control/flip_plan/flip_problem.hpp"
#include "control/jump/flip_trajectory.hpp"
#include "core/number_text.hpp"

namespace {

using namespace cerebellum;

int usage() {
  std::fprintf(stderr, "usage: plan_flip [--torque-max-nm X] [--turn-rad R] [--iterations N] [--intervals A,B,C] [--stance-force-min-n F] [--landing-distance-max-m D] [--phase-max-s A,B,C] [--last-pair front|rear] [--out PATH]\n");
  return 2;
}

FlipTrajectory trajectory_of(const flip::FlipPlan& plan) {
  FlipTrajectory trajectory;
  for (const flip::FlipKnot& knot : plan.knots)
    trajectory.samples.push_back({knot.time_s, knot.phase, knot.trunk, knot.q_rad, knot.qd_rad_s, knot.tau_nm});
  return trajectory;
}

std::vector<std::string> comment_of(const flip::FlipRequest& request, const flip::FlipPlan& plan) {
  return {std::string("cerebellum flip file: ") + (request.pitch_turn_rad > 0.0 ? "a front flip" : "a back flip") +
              " planned by bench/plan_flip (docs/jumps.md, \"Flips\")",
          "solver: IPOPT, trapezoidal collocation of the planar model; status: " + plan.status + "; feasible: " +
              (plan.feasible ? "yes" : "no") + " (largest violation " + number_text(plan.max_constraint_violation, 3) + ")",
          "torque limit " + number_text(request.limits.torque_max_nm, 4) + " Nm per motor, friction " +
              number_text(request.limits.friction_mu, 3) + ", touchdown within " +
              number_text(request.limits.landing_distance_max_m, 3) + " m of the start, turn " +
              number_text(plan.pitch_turned_rad, 5) + " rad",
          "phases (s): both pairs push " + number_text(plan.duration_s[0], 4) + ", the last pair pushes " +
              number_text(plan.duration_s[1], 4) + ", flight " + number_text(plan.duration_s[2], 4),
          "per motor: front hip, front knee, rear hip, rear knee; the two legs of a pair alike; SDK signs"};
}

}  // namespace

int main(int argc, char** argv) {
  flip::FlipRequest request;
  std::string out_path;
  bool turn_given = false;
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if (i + 1 >= argc) return usage();
    const std::string value = argv[++i];
    const std::optional<double> number = finite_number(value);
    if (option == "--out") {
      out_path = value;
    } else if (option == "--intervals") {
      if (std::sscanf(value.c_str(), "%d,%d,%d", &request.intervals[0], &request.intervals[1], &request.intervals[2]) != 3)
        return usage();
    } else if (option == "--phase-max-s") {
      std::array<double, flip::kFlipPhases> bound{};
      if (std::sscanf(value.c_str(), "%lf,%lf,%lf", &bound[0], &bound[1], &bound[2]) != 3) return usage();
      for (int p = 0; p < flip::kFlipPhases; ++p)
        if (!(bound[p] >= request.duration_min_s[p])) return usage();
      request.duration_max_s = bound;
    } else if (option == "--last-pair") {
      if (value != "front" && value != "rear") return usage();
      request.last_pushing_pair = value == "front" ? flip::kFrontPairLast : flip::kRearPairLast;
    } else if (!number) {
      return usage();
    } else if (option == "--torque-max-nm") {
      request.limits.torque_max_nm = *number;
    } else if (option == "--turn-rad") {
      request.pitch_turn_rad = *number;
      turn_given = true;
    } else if (option == "--landing-distance-max-m") {
      if (*number < 0.0) return usage();
      request.limits.landing_distance_max_m = *number;
    } else if (option == "--stance-force-min-n") {
      request.limits.stance_force_min_n = *number;
    } else if (option == "--iterations") {
      request.max_iterations = static_cast<int>(*number);
    } else {
      return usage();
    }
  }
  // a front flip turns a full turn nose down (the SDK's positive pitch) unless asked otherwise
  if (!turn_given && request.last_pushing_pair == flip::kFrontPairLast) request.pitch_turn_rad = 2.0 * robot::kPi;
  const flip::FlipPlan plan = flip::plan_flip(request);
  std::printf("status: %s\nturn: %.4f rad\npeak torque (Nm): front hip %.2f, front knee %.2f, rear hip %.2f, rear knee %.2f\n"
              "phases (s): both pairs push %.3f, the last pair pushes %.3f, flight %.3f\nlargest model residual: %.2e\nfeasible: %s (largest constraint violation %.2e)\n",
              plan.status.c_str(), plan.pitch_turned_rad, plan.peak_torque_nm[0], plan.peak_torque_nm[1],
              plan.peak_torque_nm[2], plan.peak_torque_nm[3], plan.duration_s[0], plan.duration_s[1], plan.duration_s[2],
              plan.max_dynamics_residual, plan.feasible ? "yes" : "no", plan.max_constraint_violation);
  if (out_path.empty()) return plan.feasible ? 0 : 1;
  std::ofstream file(out_path);
  file << flip_trajectory_text(trajectory_of(plan), comment_of(request, plan));
  if (!file) {
    std::fprintf(stderr, "plan_flip: cannot write %s\n", out_path.c_str());
    return 1;
  }
  std::printf("wrote %s\n", out_path.c_str());
  return plan.feasible ? 0 : 1;
}
