// Orientation from the IMU, trunk height and contacts from leg kinematics: the estimate that
// needs no gait knowledge. Position and velocity come from the Kalman filter stage built on it.
#pragma once

#include "estimation/state_estimator.hpp"

namespace cerebellum {

struct KinematicEstimatorConfig {
  double contact_force_threshold_n = 5.0;  // foot force above this counts as contact
};

class KinematicEstimator : public StateEstimator {
 public:
  explicit KinematicEstimator(const KinematicEstimatorConfig& config = {});
  void reset() override;
  // contacts come from the foot forces alone: the plan is not used
  void update(const SensorFrame& frame, const ContactPlan& plan, RobotState& state) override;

 private:
  KinematicEstimatorConfig config_;
};

// true when every number in the frame is finite
bool sensor_frame_is_finite(const SensorFrame& frame);

}  // namespace cerebellum
