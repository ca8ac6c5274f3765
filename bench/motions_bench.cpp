// Named motions (mode 62) over seeded runs with sensor noise: for each shipped motion, its time,
// the lowest trunk height, the largest roll/pitch, the peak joint torque, the largest motor
// temperature rise, falls, and how far the robot ends from the stand pose it started in. Control
// runs on the robot's own noisy estimate; the simulator's truth only scores. Prints a markdown
// table (docs/benchmarks.md).
//   motions_bench [--seeds=101-120] [--two-leg-only]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "loop/lockstep_client.hpp"
#include "loop/simulated_robot.hpp"
#include "soak_support.hpp"
#include "core/orientation.hpp"
#include "motions/motion_folder.hpp"

namespace {

using namespace cerebellum;

struct Figures {
  double duration_s = 0.0;
  double lowest_height_m = 1.0;
  double largest_tilt_rad = 0.0;
  double peak_torque_nm = 0.0;
  double temperature_rise_c = 0.0;
  bool fell = false;
  double end_height_error_m = 0.0;
  double end_tilt_error_rad = 0.0;
};

Eigen::Vector3d rpy_of(const GroundTruth& g) {
  return rpy_from_quaternion(Eigen::Quaterniond(g.quat[0], g.quat[1], g.quat[2], g.quat[3]));
}

// mode 62 with the motion id, or mode 64 (id 0): the two-leg stand tilts the trunk on purpose, so
// its fall is what the MC reports (damping, a lie-down) or a trunk below 0.1 m
Figures run_motion(ModeId mode, int id, unsigned seed) {
  const bool two_leg = mode == ModeId::TwoLegStand;
  Mc mc = make_simulated_mc(bench::soak_config(seed));
  LockstepClient client(mc);
  client.run(high_level_command(ModeId::RecoveryStand, 0), 3.0);
  client.run(high_level_command(ModeId::PoseControl, 0), 1.5);  // the stand pose
  const GroundTruth before = mc.simulation().ground_truth();
  const Eigen::Vector3d rpy_before = rpy_of(before);
  JointArray<double> temperature_before{};
  Figures f;
  bool first = true;
  bool done = false;
  const double start = mc.backend().time_s();
  // the motion's entry ends with the motion; then the queue holds the pose (21/3) for 1 s
  HighLevelCommand command = high_level_command(mode, id);
  command.life_count = 100;  // new after the client's few commands
  double next_send = start;
  double end = start + 60.0;
  while (mc.backend().time_s() < end) {
    if (mc.backend().time_s() >= next_send - 1e-9) {
      mc.machine().submit(command, mc.backend().time_s());  // the same life_count: a heartbeat
      next_send += LockstepClient::kHeartbeatPeriodS;
    }
    const CycleRecord& record = mc.loop().tick();
    if (first) temperature_before = record.state.temperature_c;
    first = false;
    const GroundTruth g = mc.simulation().ground_truth();
    const Eigen::Vector3d rpy = rpy_of(g);
    f.lowest_height_m = std::min(f.lowest_height_m, g.position[2]);
    f.largest_tilt_rad = std::max({f.largest_tilt_rad, std::abs(rpy.x()), std::abs(rpy.y())});
    const HighLevelStatus& now = mc.machine().status();
    f.fell |= two_leg ? now.mode != static_cast<int>(mode) || now.switch_status == SwitchStatus::HighDamping ||
                            g.position[2] < 0.1
                      : std::abs(rpy.x()) > 1.0 || std::abs(rpy.y()) > 1.0 || g.position[2] < 0.1;
    for (std::size_t j = 0; j < kNumJoints; ++j) {
      f.peak_torque_nm = std::max(f.peak_torque_nm, std::abs(g.tau[j]));
      f.temperature_rise_c = std::max(f.temperature_rise_c, record.state.temperature_c[j] - temperature_before[j]);
    }
    const HighLevelStatus& status = mc.machine().status();
    if (!done && status.mode == static_cast<int>(mode) && status.order_process_bar == 100) {
      done = true;
      f.duration_s = mc.backend().time_s() - start;
      end = mc.backend().time_s() + 1.0;
    }
  }
  if (!done) f.duration_s = std::nan("");
  const GroundTruth after = mc.simulation().ground_truth();
  const Eigen::Vector3d rpy_after = rpy_of(after);
  f.end_height_error_m = std::abs(after.position[2] - before.position[2]);
  f.end_tilt_error_rad = std::max(std::abs(rpy_after.x() - rpy_before.x()), std::abs(rpy_after.y() - rpy_before.y()));
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  unsigned first_seed = 101;
  unsigned last_seed = 120;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--seeds=", 0) == 0) {
      const std::string range = arg.substr(8);
      const std::size_t dash = range.find('-');
      first_seed = static_cast<unsigned>(std::stoul(range.substr(0, dash)));
      last_seed = dash == std::string::npos ? first_seed : static_cast<unsigned>(std::stoul(range.substr(dash + 1)));
    }
  }
  bool two_leg_only = false;
  for (int i = 1; i < argc; ++i) two_leg_only |= std::string(argv[i]) == "--two-leg-only";
  const MotionLibrary library = load_motion_library(default_config().motions);
  std::printf(
      "| motion | runs | time (s) | lowest trunk (m) | largest tilt (rad) | peak torque (Nm) | "
      "temperature rise (deg C) | falls | end height / tilt error (mm / rad) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  const auto report = [&](ModeId mode, int id, const std::string& name) {
    std::vector<Figures> runs;
    for (unsigned seed = first_seed; seed <= last_seed; ++seed) runs.push_back(run_motion(mode, id, seed));
    Figures worst;
    double mean_time = 0.0;
    int falls = 0;
    for (const Figures& f : runs) {
      mean_time += f.duration_s / static_cast<double>(runs.size());
      worst.lowest_height_m = std::min(worst.lowest_height_m, f.lowest_height_m);
      worst.largest_tilt_rad = std::max(worst.largest_tilt_rad, f.largest_tilt_rad);
      worst.peak_torque_nm = std::max(worst.peak_torque_nm, f.peak_torque_nm);
      worst.temperature_rise_c = std::max(worst.temperature_rise_c, f.temperature_rise_c);
      worst.end_height_error_m = std::max(worst.end_height_error_m, f.end_height_error_m);
      worst.end_tilt_error_rad = std::max(worst.end_tilt_error_rad, f.end_tilt_error_rad);
      falls += f.fell ? 1 : 0;
    }
    std::printf("| %s | %zu | %.2f | %.3f | %.3f | %.1f | %.2f | %d | %.1f / %.3f |\n", name.c_str(), runs.size(),
                mean_time, worst.lowest_height_m, worst.largest_tilt_rad, worst.peak_torque_nm,
                worst.temperature_rise_c, falls, 1e3 * worst.end_height_error_m, worst.end_tilt_error_rad);
    std::fflush(stdout);
  };
  if (!two_leg_only) {
    for (const Motion& motion : library.motions()) {
      report(ModeId::Motion, motion.id, std::to_string(motion.id) + " " + motion.name);
    }
  }
  // its largest tilt is the trunk's pitch when upright (about 1.5 rad), on purpose
  report(ModeId::TwoLegStand, 0, "64 two-leg stand");
  return 0;
}
