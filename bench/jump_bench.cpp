// Jumps (mode 16) over seeded runs with sensor noise: for each jump id, what it reached (trunk
// displacement, turn, apex rise above the stand), the flight time, the landing impact (peak
// vertical ground force summed over the feet, from the simulator's contact forces), the peak joint
// torque and motor temperature rise, and falls; and the plan's compute time. Control runs on the
// robot's own noisy estimate; the simulator's truth only scores. Prints a markdown table
// (docs/jumps.md).
//   jump_bench [--seeds=401-450] [--jumps=0,1,4] [--verbose]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "loop/lockstep_client.hpp"
#include "loop/simulated_robot.hpp"
#include "core/orientation.hpp"
#include "modes/jump_mode.hpp"
#include "soak_support.hpp"

namespace {

using namespace cerebellum;

struct Figures {
  Eigen::Vector2d displacement_m = Eigen::Vector2d::Zero();  // heading frame at the start
  double turn_rad = 0.0;
  double apex_rise_m = 0.0;
  double flight_s = 0.0;
  double peak_force_n = 0.0;
  double peak_torque_nm = 0.0;
  double temperature_rise_c = 0.0;
  double largest_tilt_rad = 0.0;  // roll or pitch, from the command until the end
  bool on_target = false;         // within the tolerance of the jump's target
  bool fell = false;
  bool stood = false;  // the response said 100 and the robot stands
};

Eigen::Vector3d rpy_of(const GroundTruth& g) {
  return rpy_from_quaternion(Eigen::Quaterniond(g.quat[0], g.quat[1], g.quat[2], g.quat[3]));
}

// the ground's vertical force on the four feet, from the simulator's contacts
double vertical_foot_force(const GroundTruth& g) {
  return g.foot_force_z_n[0] + g.foot_force_z_n[1] + g.foot_force_z_n[2] + g.foot_force_z_n[3];
}

Figures run_jump(int id, long seed, bool verbose) {
  McConfig config = bench::soak_config(seed);
  // the jump down a stair starts on a 10 cm landing whose edge is just past the front feet
  if (id == 9) {
    config.robot.model_path = std::string(CEREBELLUM_MODEL_DIR) + "/terrain_stair_down10cm.xml";
    config.robot.initial_height_m = 0.4;
  }
  Mc mc = make_simulated_mc(config);
  LockstepClient client(mc);
  client.run(high_level_command(ModeId::RecoveryStand, 0), 3.0);
  client.run(high_level_command(ModeId::Locomotion, 1), 1.0);
  const GroundTruth before = mc.simulation().ground_truth();
  const double yaw0 = rpy_of(before).z();
  JointArray<double> temperature_before = mc.loop().last_cycle().state.temperature_c;
  Figures f;
  bool in_air = false;
  double left_ground_s = 0.0;
  double end = mc.backend().time_s() + 6.0;
  bool done = false;
  const double start = mc.backend().time_s();
  const HighLevelCommand command = high_level_command(ModeId::Jump3d, id);
  client.run(command, 6.0, [&](const CycleRecord& record) {
    const GroundTruth g = mc.simulation().ground_truth();
    const Eigen::Vector3d rpy = rpy_of(g);
    const bool airborne = std::none_of(g.foot_contact.begin(), g.foot_contact.end(), [](bool c) { return c; });
    const double now = mc.backend().time_s();
    if (airborne && !in_air) left_ground_s = now;
    if (!airborne && in_air && now - left_ground_s > 0.03) f.flight_s = std::max(f.flight_s, now - left_ground_s);
    in_air = airborne;
    f.apex_rise_m = std::max(f.apex_rise_m, g.position[2] - before.position[2]);
    f.peak_force_n = std::max(f.peak_force_n, vertical_foot_force(g));
    f.largest_tilt_rad = std::max({f.largest_tilt_rad, std::abs(rpy.x()), std::abs(rpy.y())});
    f.fell |= std::abs(rpy.x()) > 1.0 || std::abs(rpy.y()) > 1.0 || g.position[2] < 0.1;
    for (std::size_t j = 0; j < kNumJoints; ++j) {
      f.peak_torque_nm = std::max(f.peak_torque_nm, std::abs(g.tau[j]));
      f.temperature_rise_c = std::max(f.temperature_rise_c, record.state.temperature_c[j] - temperature_before[j]);
    }
    const HighLevelStatus& status = mc.machine().status();
    if (verbose && static_cast<long>(std::lround((now - start) * 500)) % 10 == 0 && now - start < 1.5) {
      const JumpController& jump = mc.modes().jump().controller();
      std::printf(
          "  t=%.3f %-8s mode=%d/%d bar=%3d x=%.3f y=%.3f z=%.3f roll=%.2f pitch=%.2f yaw=%.2f vx=%.2f vz=%.2f "
          "contacts=%d%d%d%d\n",
          now - start, jump_phase_name(jump.phase()), status.mode, static_cast<int>(status.switch_status),
          status.order_process_bar, g.position[0] - before.position[0], g.position[1] - before.position[1],
          g.position[2], rpy.x(), rpy.y(), rpy.z() - yaw0, g.velocity_world[0], g.velocity_world[2], g.foot_contact[0],
          g.foot_contact[1], g.foot_contact[2], g.foot_contact[3]);
    }
    if (verbose && now - start < 0.0025) {
      const JumpPlan& plan = mc.modes().jump().controller().plan();
      std::printf(
          "  plan: push %.3f s, trunk v (%.2f %.2f %.2f), com v (%.2f %.2f %.2f), flight %.3f s, K diag %.2f %.2f "
          "%.2f, "
          "crouch %.3f stroke %.3f flight %.3f offset %.3f, yaw rate %.2f, tilt rates %.2f %.2f, foot offset %.3f, "
          "shortfall %s\n",
          plan.push_duration_s, plan.takeoff_velocity_m_s.x(), plan.takeoff_velocity_m_s.y(),
          plan.takeoff_velocity_m_s.z(), plan.com_takeoff_velocity_m_s.x(), plan.com_takeoff_velocity_m_s.y(),
          plan.com_takeoff_velocity_m_s.z(), plan.flight_duration_s, plan.momentum_map(0, 0), plan.momentum_map(1, 1),
          plan.momentum_map(2, 2), plan.crouch_offset_m.x(), plan.push_stroke_m.x(), plan.flight_travel_m.x(),
          plan.landing_foot_offset_m.x(), plan.yaw_rate_rad_s, plan.takeoff_tilt_rate_rad_s.x(),
          plan.takeoff_tilt_rate_rad_s.y(), plan.landing_foot_offset_m.norm(), jump_shortfall_text(plan.shortfall));
    }
    if (verbose && record.health.causes != 0) {
      std::printf("  health causes %u motors %x battery %.2f V %.1f A faults FRk %x\n", record.health.causes,
                  record.health.faulty_motors, record.state.battery.voltage_v, record.state.battery.current_a,
                  record.state.motor_faults[2]);
    }
    if (!done && status.mode == static_cast<int>(ModeId::Jump3d) && status.order_process_bar == 100) done = true;
  });
  (void)end;
  const GroundTruth after = mc.simulation().ground_truth();
  const Eigen::Vector2d moved(after.position[0] - before.position[0], after.position[1] - before.position[1]);
  f.displacement_m = Eigen::Rotation2Dd(-yaw0) * moved;
  f.turn_rad = std::remainder(rpy_of(after).z() - yaw0, 2.0 * robot::kPi);
  f.stood = done && !f.fell && after.position[2] > 0.2;
  return f;
}

// the reach the issue asks: a distance within 15 % (or 5 cm), a turn within 10 deg, the up
// jump's rise within 15 %; the stair jump has no target (false)
bool on_target(const JumpSpec& spec, const Figures& f) {
  if (spec.landing_ground_m < 0.0) return false;
  const Eigen::Vector2d target(spec.forward_m, spec.left_m);
  const bool distance =
      target.norm() < 1e-9 || (f.displacement_m - target).norm() <= std::max(0.15 * target.norm(), 0.05);
  const bool turn = std::abs(f.turn_rad * 180.0 / robot::kPi - spec.turn_deg) <= 10.0;
  const bool rise = spec.apex_rise_m <= 0.0 || std::abs(f.apex_rise_m - spec.apex_rise_m) <= 0.15 * spec.apex_rise_m;
  return distance && turn && rise;
}

}  // namespace

int main(int argc, char** argv) {
  long first_seed = 401;
  long last_seed = 450;
  bool verbose = false;
  std::vector<int> ids;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--seeds=", 0) == 0) {
      const std::string range = arg.substr(8);
      const std::size_t dash = range.find('-');
      first_seed = std::stol(range.substr(0, dash));
      last_seed = dash == std::string::npos ? first_seed : std::stol(range.substr(dash + 1));
    } else if (arg.rfind("--jumps=", 0) == 0) {
      std::size_t pos = 8;
      while (pos < arg.size()) {
        const std::size_t comma = arg.find(',', pos);
        ids.push_back(std::stoi(arg.substr(pos, comma - pos)));
        pos = comma == std::string::npos ? arg.size() : comma + 1;
      }
    } else if (arg == "--verbose") {
      verbose = true;
    } else if (arg.rfind("--benchmark_", 0) == 0) {
      // bench/run.sh's Google Benchmark options: this benchmark prints its own table
    } else {
      std::fprintf(stderr, "usage: jump_bench [--seeds=A-B] [--jumps=0,1,...] [--verbose]\n");
      return 2;
    }
  }
  if (ids.empty()) {
    for (const JumpSpec& spec : kJump3dTable) ids.push_back(spec.gait_id);
  }
  std::printf(
      "| jump | target | runs | reached: forward, left (m) | turn (deg) | apex rise (m) | flight (s) | "
      "peak foot force (N) | peak torque (Nm) | temperature rise (deg C) | largest tilt (rad) | on target | falls | "
      "stood |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const int id : ids) {
    const JumpSpec* spec = find_jump(id);
    if (spec == nullptr) continue;
    std::vector<Figures> runs;
    for (long seed = first_seed; seed <= last_seed; ++seed) runs.push_back(run_jump(id, seed, verbose));
    Figures mean;
    Figures worst;
    int falls = 0;
    int stood = 0;
    int hits = 0;
    const double n = static_cast<double>(runs.size());
    for (const Figures& f : runs) {
      mean.displacement_m += f.displacement_m / n;
      mean.turn_rad += f.turn_rad / n;
      mean.apex_rise_m += f.apex_rise_m / n;
      mean.flight_s += f.flight_s / n;
      worst.peak_force_n = std::max(worst.peak_force_n, f.peak_force_n);
      worst.peak_torque_nm = std::max(worst.peak_torque_nm, f.peak_torque_nm);
      worst.temperature_rise_c = std::max(worst.temperature_rise_c, f.temperature_rise_c);
      worst.largest_tilt_rad = std::max(worst.largest_tilt_rad, f.largest_tilt_rad);
      hits += on_target(*spec, f) ? 1 : 0;
      falls += f.fell ? 1 : 0;
      stood += f.stood ? 1 : 0;
    }
    const std::string target_column = spec->landing_ground_m < 0.0 ? "-" : std::to_string(hits);
    std::printf("| %d | %s | %zu | %.3f, %.3f | %.1f | %.3f | %.3f | %.0f | %.1f | %.2f | %.2f | %s | %d | %d |\n", id,
                spec->name, runs.size(), mean.displacement_m.x(), mean.displacement_m.y(),
                mean.turn_rad * 180.0 / robot::kPi, mean.apex_rise_m, mean.flight_s, worst.peak_force_n,
                worst.peak_torque_nm, worst.temperature_rise_c, worst.largest_tilt_rad, target_column.c_str(), falls,
                stood);
    std::fflush(stdout);
  }
  // the plan's compute time: it runs once, inside the tick that receives the command
  std::vector<double> micros;
  const JumpLimits limits = default_jump_controller_config().limits;
  for (int i = 0; i < 2000; ++i) {
    const JumpSpec& spec = kJump3dTable[static_cast<std::size_t>(i) % kJump3dTable.size()];
    const auto t0 = std::chrono::steady_clock::now();
    const JumpPlan plan = plan_jump(jump_target(spec), limits);
    const auto t1 = std::chrono::steady_clock::now();
    if (plan.push_duration_s <= 0.0) return 1;
    micros.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
  }
  std::sort(micros.begin(), micros.end());
  std::printf("\nplan_jump compute time: p50 %.2f us, p99 %.2f us (%zu plans)\n", micros[micros.size() / 2],
              micros[micros.size() * 99 / 100], micros.size());
  return 0;
}
