#include "control/pose_ramp.hpp"

#include <algorithm>
#include <cmath>

#include "control/stand_up_controller.hpp"
#include "control/joint_ramp.hpp"

namespace cerebellum {

double move_duration_s(const BodyPose& from, const BodyPose& to, const PoseSpeed& speed) {
  const double angle = (to.rpy - from.rpy).cwiseAbs().maxCoeff();
  const double distance = (to.position - from.position).norm();
  // a smooth-step move peaks at pi/2 times its mean speed
  const double factor = 1.5707963267948966;
  return std::max({speed.min_duration_s, factor * angle / speed.angular_rad_s, factor * distance / speed.linear_m_s});
}

void PoseRamp::hold(const BodyPose& pose) {
  from_ = goal_ = value_ = pose;
  rate_ = BodyPose{};
  duration_s_ = elapsed_s_ = 0.0;
}

void PoseRamp::move_to(const BodyPose& goal, double duration_s) {
  // the goal already pursued: the running move goes on unchanged
  if (goal.rpy == goal_.rpy && goal.position == goal_.position) return;
  from_ = value_;
  goal_ = goal;
  duration_s_ = std::max(duration_s, 0.0);
  elapsed_s_ = 0.0;
}

void PoseRamp::advance(double dt_s) {
  elapsed_s_ = std::min(elapsed_s_ + dt_s, duration_s_);
  const double s = smooth_step(fraction());
  value_.rpy = from_.rpy + (goal_.rpy - from_.rpy) * s;
  value_.position = from_.position + (goal_.position - from_.position) * s;
  // d/dt of 0.5 - 0.5 cos(pi t / T)
  const double ds_dt =
      arrived() ? 0.0 : 0.5 * 3.14159265358979323846 * std::sin(3.14159265358979323846 * fraction()) / duration_s_;
  rate_.rpy = (goal_.rpy - from_.rpy) * ds_dt;
  rate_.position = (goal_.position - from_.position) * ds_dt;
}

double PoseRamp::fraction() const { return duration_s_ > 0.0 ? std::clamp(elapsed_s_ / duration_s_, 0.0, 1.0) : 1.0; }

}  // namespace cerebellum
