// The full trunk state: orientation, acceleration and contacts from the kinematic estimator,
// position, velocity and height from the linear Kalman filter over trunk and feet.
#pragma once

#include <array>

#include "core/contact_plan.hpp"
#include "estimation/ground_plane_tracker.hpp"
#include "estimation/kinematic_estimator.hpp"
#include "estimation/linear_kalman_filter.hpp"

namespace cerebellum {

struct BodyStateEstimatorConfig {
  KinematicEstimatorConfig kinematic;
  LinearKalmanFilterConfig filter;
  // the feet's height measurement is the ground plane through the recently planted feet
  GroundPlaneTrackerConfig ground;
  double planted_trust = 0.9;  // a foot counts for the plane from this trust on
  // trust of a foot the force estimate reports in contact rises linearly over this time (s)
  double force_contact_ramp_s = 0.02;
  // with a schedule, trust rises over this fraction of the stance at its start and falls over it at its end
  double schedule_ramp_fraction = 0.1;
  // a longer gap between frames is predicted as this step (s)
  double max_step_s = 0.02;
};

// trust of a foot from the force estimate: probability ramped in over time_in_contact_s / ramp_s
double force_contact_trust(double contact_probability, double time_in_contact_s, double ramp_s);
// trust of a foot from a schedule: probability ramped in and out at both ends of the stance
double scheduled_contact_trust(const LegContactPlan& plan, double ramp_fraction);
// the trunk origin's acceleration (world) from the IMU's (world, gravity removed) at imu_body:
// a - R (alpha x r + omega x (omega x r)), body rates in the body frame. Uncorrected, a bound's
// pitching (4 rad/s, 100 rad/s^2) puts about 6 m/s^2 into the prediction that the legs had to undo
Eigen::Vector3d trunk_origin_acceleration(const Eigen::Vector3d& imu_accel_world, const Eigen::Matrix3d& body_to_world,
                                          const Eigen::Vector3d& omega_body, const Eigen::Vector3d& alpha_body,
                                          const Eigen::Vector3d& imu_body);

class BodyStateEstimator final : public StateEstimator {
 public:
  explicit BodyStateEstimator(const BodyStateEstimatorConfig& config = {});
  void reset() override;
  // with a plan, its contacts are trusted instead of the force estimate; a plan with non-finite
  // numbers is refused (the previous choice stays)
  void update(const SensorFrame& frame, const ContactPlan& plan, RobotState& state) override;

  const LinearKalmanFilter& filter() const { return filter_; }
  // per leg 0..1, as handed to the filter on the last update
  const LinearKalmanFilter::Trust& contact_trust() const { return trust_; }

 private:
  void follow_plan(const ContactPlan& plan);
  void update_trust(const RobotState& state, double dt_s);
  void start_filter(const RobotState& state);
  LegObservations observe_legs(const RobotState& state) const;
  void write_state(RobotState& state);
  std::array<Eigen::Vector3d, kNumLegs> filter_feet() const;

  BodyStateEstimatorConfig config_;
  KinematicEstimator kinematic_;
  LinearKalmanFilter filter_;
  GroundPlaneTracker ground_;
  ContactPlan schedule_;  // the plan in use
  LinearKalmanFilter::Trust trust_{};
  std::array<double, kNumLegs> time_in_contact_s_{};
  double last_time_s_ = 0.0;
  Eigen::Vector3d last_omega_body_ = Eigen::Vector3d::Zero();  // for the angular acceleration
  double ground_z_m_ = 0.0;  // world z under the stance feet, kept through flight phases
};

}  // namespace cerebellum
