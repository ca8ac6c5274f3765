#include "control/jump/flip_player.hpp"

#include <algorithm>

#include "core/joint_layout.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {

FlipSample flip_sample_at(const FlipTrajectory& trajectory, double t_s) {
  const std::vector<FlipSample>& s = trajectory.samples;
  if (t_s <= s.front().time_s) return s.front();
  if (t_s >= s.back().time_s) return s.back();
  const auto next = std::upper_bound(s.begin(), s.end(), t_s, [](double t, const FlipSample& k) { return t < k.time_s; });
  const FlipSample& b = *next;
  const FlipSample& a = *(next - 1);
  const double w = (t_s - a.time_s) / (b.time_s - a.time_s);
  FlipSample out = a;
  out.time_s = t_s;
  for (int i = 0; i < 3; ++i) out.trunk[i] = a.trunk[i] + w * (b.trunk[i] - a.trunk[i]);
  for (int m = 0; m < kFlipMotors; ++m) {
    out.q_rad[m] = a.q_rad[m] + w * (b.q_rad[m] - a.q_rad[m]);
    out.qd_rad_s[m] = a.qd_rad_s[m] + w * (b.qd_rad_s[m] - a.qd_rad_s[m]);
    out.tau_nm[m] = a.tau_nm[m] + w * (b.tau_nm[m] - a.tau_nm[m]);
  }
  return out;
}

JointCommand flip_play_command(const FlipTrajectory& trajectory, double t_s, const FlipPlayGains& gains) {
  const FlipSample sample = flip_sample_at(trajectory, t_s);
  // past the end the legs hold the landing pose, not its rates or torques
  const bool ended = t_s >= flip_duration_s(trajectory);
  JointCommand command{};
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const std::size_t j = leg * kJointsPerLeg;
    command.q_des[j] = 0.0;
    command.qd_des[j] = 0.0;
    command.kp[j] = gains.abad_kp;
    command.kd[j] = gains.abad_kd;
    command.tau_ff[j] = 0.0;
    // the pair's hip and knee: motors 0, 1 (front) or 2, 3 (rear)
    const int first = is_front_leg(leg) ? 0 : 2;
    for (int k = 0; k < 2; ++k) {
      const double qd_rad_s = ended ? 0.0 : sample.qd_rad_s[first + k];
      // the interface takes qd_des within +-12 rad/s (the guard clamps it there) while the plan
      // turns joints up to the motors' 30.5: the rate beyond goes into the feed-forward as the
      // damping term it stands for, so the motor law gives the same torque
      const double qd_des = std::clamp(qd_rad_s, -robot::kCommandQdDesMaxRadS, robot::kCommandQdDesMaxRadS);
      const double tau_ff = (ended ? 0.0 : sample.tau_nm[first + k]) + gains.kd * (qd_rad_s - qd_des);
      command.q_des[j + 1 + k] = sample.q_rad[first + k];
      command.qd_des[j + 1 + k] = qd_des;
      command.kp[j + 1 + k] = gains.kp;
      command.kd[j + 1 + k] = gains.kd;
      command.tau_ff[j + 1 + k] = std::clamp(tau_ff, -robot::kTorqueMaxNm, robot::kTorqueMaxNm);
    }
  }
  return command;
}

}  // namespace cerebellum
