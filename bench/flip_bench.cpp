// The back flip (16/20) through the whole MC over seeded runs with sensor noise, judged on the
// simulator's truth: pitch turned (the trunk's pitch rate integrated from the command on), the
// distance from the take-off to where it stands, the peak motor torque, the hottest winding's
// rise, falls (tilt past 1 rad or trunk below 0.1 m once the landing has begun, or damped) and
// runs that stood (the response at 100 and the trunk above 0.2 m, level within 0.1 rad).
//   flip_bench [--seeds=A-B]   (default 501-520: seeds never used to tune the flip)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/orientation.hpp"
#include "loop/lockstep_client.hpp"
#include "loop/simulated_robot.hpp"
#include "modes/jump_mode.hpp"
#include "soak_support.hpp"

namespace {

using namespace cerebellum;

Eigen::Vector3d rpy_of(const GroundTruth& g) {
  return rpy_from_quaternion(Eigen::Quaterniond(g.quat[0], g.quat[1], g.quat[2], g.quat[3]));
}

struct FlipFigures {
  double turned_rad = 0.0;
  double distance_m = 0.0;
  double peak_torque_nm = 0.0;
  double temperature_rise_c = 0.0;
  bool fell = false;
  bool stood = false;
};

FlipFigures run_flip(long seed) {
  Mc mc = make_simulated_mc(bench::soak_config(seed));
  LockstepClient client(mc);
  client.run(high_level_command(ModeId::RecoveryStand, 0), 3.0);
  client.run(high_level_command(ModeId::Locomotion, 1), 1.0);
  const GroundTruth before = mc.simulation().ground_truth();
  const JointArray<double> temperature_before = mc.loop().last_cycle().state.temperature_c;
  FlipFigures f;
  client.run(high_level_command(ModeId::Jump3d, kBackFlipGaitId), 5.0, [&](const CycleRecord& record) {
    const GroundTruth g = mc.simulation().ground_truth();
    f.turned_rad += g.angular_velocity_body[1] * mc.config().loop_period_s;
    for (std::size_t j = 0; j < kNumJoints; ++j) {
      f.peak_torque_nm = std::max(f.peak_torque_nm, std::abs(g.tau[j]));
      f.temperature_rise_c = std::max(f.temperature_rise_c, record.state.temperature_c[j] - temperature_before[j]);
    }
    const HighLevelStatus& s = mc.machine().status();
    f.fell |= s.mode == static_cast<int>(ModeId::PureDamper);
    // upside down is the flip itself; once the jump controller lands it, a tilt is a fall
    if (mc.modes().jump().controller().phase() == JumpPhase::Landing ||
        mc.modes().jump().controller().phase() == JumpPhase::Standing) {
      const Eigen::Vector3d rpy = rpy_of(g);
      f.fell |= std::abs(rpy.x()) > 1.0 || std::abs(rpy.y()) > 1.0 || g.position[2] < 0.1;
    }
  });
  const GroundTruth after = mc.simulation().ground_truth();
  f.distance_m = std::hypot(after.position[0] - before.position[0], after.position[1] - before.position[1]);
  const Eigen::Vector3d rpy = rpy_of(after);
  const HighLevelStatus& s = mc.machine().status();
  f.stood = !f.fell && s.mode == static_cast<int>(ModeId::Jump3d) && s.order_process_bar == 100 &&
            after.position[2] > 0.2 && std::max(std::abs(rpy.x()), std::abs(rpy.y())) < 0.1;
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  long first = 501, last = 520;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--seeds=", 0) == 0 && std::sscanf(arg.c_str() + 8, "%ld-%ld", &first, &last) == 2 && first <= last) continue;
    std::fprintf(stderr, "usage: flip_bench [--seeds=A-B]\n");
    return 2;
  }
  std::printf("| seed | turned (rad) | distance from take-off (m) | peak torque (Nm) | temperature rise (deg C) | fell | stood |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  int stood = 0, fell = 0;
  for (long seed = first; seed <= last; ++seed) {
    const FlipFigures f = run_flip(seed);
    stood += f.stood ? 1 : 0;
    fell += f.fell ? 1 : 0;
    std::printf("| %ld | %.4f | %.4f | %.2f | %.3f | %s | %s |\n", seed, f.turned_rad, f.distance_m, f.peak_torque_nm,
                f.temperature_rise_c, f.fell ? "yes" : "no", f.stood ? "yes" : "no");
    std::fflush(stdout);
  }
  std::printf("stood: %d of %ld, fell: %d\n", stood, last - first + 1, fell);
  return 0;
}
