// The passive trot's ("walk the dog", gait 4) compliance: it estimates the horizontal force that a
// leash or a hand puts on the trunk and turns it into a walking velocity (an admittance), and says
// when the robot should step and when it may stand again.
#pragma once

#include <Eigen/Core>

#include "core/robot_model.hpp"
#include "core/robot_state.hpp"

namespace cerebellum {

struct PassiveFollowConfig {
  double mass_kg = robot::kTotalMassKg;
  // low-pass time constant of the force estimate: the trot's stance forces swing every half cycle
  double force_filter_s = 0.15;
  // the estimate's slow error while standing (the legs' own weight and joint friction in the
  // torques, a stance that is not symmetric) is learnt with this time constant while no pull is
  // followed and the estimate stays inside the deadband, and taken off
  double bias_time_constant_s = 1.0;
  // estimate noise while standing or trotting in place stays below this (N)
  double deadband_n = 4.0;
  // a force above this for start_hold_s starts the trot
  double start_force_n = 7.0;
  double start_hold_s = 0.2;
  // admittance: velocity = force / damping at steady state, reached with mass / damping
  double damping_n_s_per_m = 30.0;
  double virtual_mass_kg = 6.0;
  // left alone (follow velocity below stop_speed_m_s and the force below start_force_n for
  // stop_hold_s): stand again. The force test is the start's: trotting in place, the estimate
  // carries a few newtons the standing bias does not take off (the swinging legs' reactions), and
  // a lower stop threshold inside that error kept the trot going by itself (issue 47); what would
  // not start a trot does not keep one going, and a real pull still does through the velocity
  double stop_speed_m_s = 0.06;
  double stop_hold_s = 0.25;
};

// the horizontal force (world x, y; N) on the trunk from outside the robot: m a minus the ground's
// forces on the feet in contact, those from the measured joint torques (tau = -J^T f, body frame)
Eigen::Vector2d external_force_world(const RobotState& state, double mass_kg);

class PassiveFollow {
 public:
  explicit PassiveFollow(const PassiveFollowConfig& config = {}) : config_(config) {}

  void reset();
  // one tick of dt_s: returns the follow velocity (world x, y; m/s)
  Eigen::Vector2d update(const RobotState& state, double dt_s);

  // true from a sustained pull until the robot has been left alone
  bool following() const { return following_; }
  const Eigen::Vector2d& force_world() const { return force_; }
  const Eigen::Vector2d& velocity_world() const { return velocity_; }

 private:
  PassiveFollowConfig config_;
  Eigen::Vector2d force_ = Eigen::Vector2d::Zero();     // filtered estimate, bias taken off
  Eigen::Vector2d filtered_ = Eigen::Vector2d::Zero();  // filtered estimate
  Eigen::Vector2d bias_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d velocity_ = Eigen::Vector2d::Zero();  // admittance state
  bool following_ = false;
  double pulled_s_ = 0.0;
  double quiet_s_ = 0.0;
};

}  // namespace cerebellum
