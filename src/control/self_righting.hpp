// Turning a robot that lies on its side or on its back over onto its belly, by joint-space
// keyframes: the legs of the lower side swing round to point over the back and push the ground
// there while the upper legs reach out on the belly side to carry the centre of mass over.
// On its back, the legs of one side first push the robot onto that side's opposite flank.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Geometry>

#include "control/motion_controller.hpp"

namespace cerebellum {

// how the trunk rests, from the direction of gravity in the body frame
enum class BodyRest { Upright, OnLeftSide, OnRightSide, UpsideDown };
BodyRest body_rest(const Eigen::Quaterniond& body_to_world);

struct SelfRightingConfig {
  double kp = 60.0;
  double kd = 1.5;
  double fold_s = 0.6;    // legs folded close to the body
  double reach_s = 0.6;   // lower legs over the back, upper legs out on the belly side
  double push_s = 0.35;   // lower legs push the ground behind the back
  double hold_s = 0.8;    // let the body fall over
};

// one pose of the legs held after a move of duration_s
struct JointKeyframe {
  JointArray<double> q{};
  double duration_s = 0.0;
};

class SelfRighting final : public MotionController {
 public:
  explicit SelfRighting(const SelfRightingConfig& config = {});
  // plan the roll for how the body rests now; upside down it first rolls onto the side given
  // by roll_to (OnLeftSide or OnRightSide)
  void start(const RobotState& state, BodyRest rest, BodyRest roll_to);
  void compute(const RobotState& state, JointCommand& command) override;
  // 0..1 through the planned keyframes
  double progress() const;
  bool done() const { return progress() >= 1.0; }

 private:
  // a keyframe given for the robot on its right side (right legs below); mirrored when the left
  // side is below (abad angles change sign)
  void add(const std::array<double, 3>& right_legs, const std::array<double, 3>& left_legs, bool mirror,
           double duration_s);

  SelfRightingConfig config_;
  std::vector<JointKeyframe> keyframes_;  // capacity reserved once
  JointArray<double> start_q_{};
  double start_time_s_ = 0.0;
  double elapsed_s_ = 0.0;
  double total_s_ = 0.0;
  bool started_ = false;
};

}  // namespace cerebellum
