#include "sweep/flip_trial.hpp"

#include <algorithm>
#include <cmath>

#include "core/orientation.hpp"
#include "loop/lockstep_client.hpp"
#include "loop/simulated_robot.hpp"
#include "modes/jump_mode.hpp"

namespace cerebellum {
namespace {

Eigen::Vector3d rpy_of(const GroundTruth& g) {
  return rpy_from_quaternion(Eigen::Quaterniond(g.quat[0], g.quat[1], g.quat[2], g.quat[3]));
}

}  // namespace

FlipTrial run_flip_trial(const McConfig& config, int flip_gait_id) {
  Mc mc = make_simulated_mc(config);
  LockstepClient client(mc);
  client.run(high_level_command(ModeId::RecoveryStand, 0), 3.0);
  client.run(high_level_command(ModeId::Locomotion, 1), 1.0);
  const GroundTruth before = mc.simulation().ground_truth();
  const JointArray<double> temperature_before = mc.loop().last_cycle().state.temperature_c;
  FlipTrial f;
  client.run(high_level_command(ModeId::Jump3d, flip_gait_id), 5.0, [&](const CycleRecord& record) {
    const GroundTruth g = mc.simulation().ground_truth();
    f.turned_rad += g.angular_velocity_body[1] * mc.config().loop_period_s;
    for (std::size_t j = 0; j < kNumJoints; ++j) {
      f.peak_torque_nm = std::max(f.peak_torque_nm, std::abs(g.tau[j]));
      f.temperature_rise_c = std::max(f.temperature_rise_c, record.state.temperature_c[j] - temperature_before[j]);
    }
    const HighLevelStatus& s = mc.machine().status();
    f.fell |= s.mode == static_cast<int>(ModeId::PureDamper);
    // upside down is the flip itself; once the jump controller lands it, a tilt is a fall
    const JumpPhase phase = mc.modes().jump().controller().phase();
    if (phase == JumpPhase::Landing || phase == JumpPhase::Standing) {
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

}  // namespace cerebellum
