// An uploaded user gait ready to run (gait 110 of modes 11 and 62), in the MC's own types: the
// interface decodes the client's definition and parameter files into it (io/lcm_highlevel), the
// UserGaitSlot hands the newest to the loop, UserGaitRunner runs it.
#pragma once

#include <atomic>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "control/locomotion/contact_sequence.hpp"
#include "control/locomotion/locomotion_controller.hpp"

namespace cerebellum {

// one parameter step: what the body and the swing legs do while it lasts
struct UserGaitStep {
  double duration_s = 0.0;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // vx, vy (m/s, body), yaw rate (rad/s)
  // how far the body moves in the step along x, y where it gives no velocity (body_pos_des x, y, m;
  // body frame like the velocity): from where the step begins, not where the gait began, so a
  // zero offset stays put after a walking step instead of walking back to the gait's start
  Eigen::Vector2d position_offset_m = Eigen::Vector2d::Zero();
  double pitch_rad = 0.0;
  double height_m = 0.0;  // trunk height above the ground
  UserStepTargets legs;   // landing points, swing heights, roll, yaw offset, friction

  // what the body is steered at: the velocity, plus the offset spread evenly over the step (the
  // controller integrates it into the position reference, as it does a given velocity)
  Eigen::Vector3d body_velocity() const;
};

struct UserGaitProgram {
  std::shared_ptr<const ContactSequence> sequence;  // the definition's sections, once
  std::vector<UserGaitStep> steps;                  // the parameters, one after the other

  double sequence_s() const;
  double steps_s() const;
  // the gait ends when both the schedule and the steps are done; then the robot stands
  double duration_s() const;
};

// the newest valid user gait: written by the interface thread, read by the loop (lock-free for
// the reader on this platform's shared_ptr atomics; the loop only copies the pointer)
class UserGaitSlot {
 public:
  void publish(std::shared_ptr<const UserGaitProgram> program) { program_.store(std::move(program)); }
  std::shared_ptr<const UserGaitProgram> current() const { return program_.load(); }

 private:
  std::atomic<std::shared_ptr<const UserGaitProgram>> program_;
};

}  // namespace cerebellum
