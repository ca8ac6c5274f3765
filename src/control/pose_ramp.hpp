// A smooth move of the body pose from where it is to a goal over a given time (zero velocity at
// both ends), and the time such a move needs at a given speed.
#pragma once

#include "control/stance_frame.hpp"

namespace cerebellum {

struct PoseSpeed {
  double angular_rad_s = 0.5;
  double linear_m_s = 0.1;
  double min_duration_s = 0.3;
};

// time to move between two poses at most this fast
double move_duration_s(const BodyPose& from, const BodyPose& to, const PoseSpeed& speed);

class PoseRamp {
 public:
  // sit at the pose
  void hold(const BodyPose& pose);
  // start a move from the current value (the goal already pursued: the move goes on)
  void move_to(const BodyPose& goal, double duration_s);
  void advance(double dt_s);

  const BodyPose& value() const { return value_; }
  // time derivative of value(): rpy rates and linear velocity
  const BodyPose& rate() const { return rate_; }
  const BodyPose& goal() const { return goal_; }
  // 0..1 of the current move; 1 once arrived
  double fraction() const;
  bool arrived() const { return elapsed_s_ >= duration_s_; }

 private:
  BodyPose from_;
  BodyPose goal_;
  BodyPose value_;
  BodyPose rate_;
  double duration_s_ = 0.0;
  double elapsed_s_ = 0.0;
};

}  // namespace cerebellum
