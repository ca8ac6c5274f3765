// Turning a robot that lies on its back or side over onto its belly, by joint-space keyframes.
// The roll goes over one flank: the legs of the other side swing over the back and lever that
// side up with a quick push, the legs of the rolling side then point over the back so the body
// tips past them onto the belly, and the levering legs reach out on the belly side to carry the
// centre of mass over. (Found by search in the simulated model: a robot on its side with folded
// legs falls onto its back, so every roll starts from the back or from a flank.)
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "control/motion_controller.hpp"

namespace cerebellum {

// how the trunk rests, from the direction of gravity in the body frame
enum class BodyRest { Upright, OnLeftSide, OnRightSide, UpsideDown };
BodyRest body_rest(const Eigen::Quaterniond& body_to_world);

struct SelfRightingConfig {
  double kp = 100.0;
  double kd = 1.5;
};

// one pose of the legs, reached by a smooth move of duration_s
struct JointKeyframe {
  JointArray<double> q{};
  double duration_s = 0.0;
};

class SelfRighting final : public MotionController {
 public:
  explicit SelfRighting(const SelfRightingConfig& config = {});
  // plan a roll over the given flank (OnLeftSide or OnRightSide: that side ends up down first)
  void start(BodyRest roll_over);
  void compute(const RobotState& state, JointCommand& command) override;
  // 0..1 through the keyframes
  double progress() const;
  bool done() const { return progress() >= 1.0; }

 private:
  SelfRightingConfig config_;
  std::vector<JointKeyframe> keyframes_;  // capacity reserved once
  JointArray<double> start_q_{};
  double start_time_s_ = 0.0;
  double elapsed_s_ = 0.0;
  double total_s_ = 0.0;
  bool started_ = false;
};

}  // namespace cerebellum
