// The body pose a client's pose commands have asked for so far, in the command's own terms
// (rpy_des as sent, x / y offsets, height), each value clamped to its mode's range. An absolute
// command sets it; an incremental one moves it from where the previous command left it. The
// seed calls mode 21 gait 0 "incremental position control" (its basic-motion example sends head
// up 0.3, then head down 0.3, and the robot ends level); the reference has mode 3 gait 0
// absolute and gaits 1 and 3 incremental.
#pragma once

#include <cmath>

#include <Eigen/Core>

#include "core/high_level_command.hpp"
#include "modes/command_ranges.hpp"

namespace cerebellum {

// The attitude a command's rpy_des asks for, as the body's ZYX angles (x forward, y left, z up,
// right-handed). The seed's pitch raises the head when positive ("rpy_des = [0, 0.3, 0] # Head
// up"), where a right-handed pitch about y (to the left) lowers it: the sign turns here and
// nowhere else. Roll (left side up) and yaw (to the left) are right-handed: the seeds say nothing
// else. Ranges clamp the command's values, so a pitch range -0.25..0.3 is 0.25 rad head down to
// 0.3 rad head up.
inline double body_pitch_from_command(double pitch_des) { return -pitch_des; }
inline Eigen::Vector3d body_rpy_from_command(const Eigen::Vector3d& rpy_des) {
  return {rpy_des.x(), body_pitch_from_command(rpy_des.y()), rpy_des.z()};
}

class CommandedPose {
 public:
  // the level stand at height_m
  void reset(double height_m) {
    rpy_des_.setZero();
    offset_m_.setZero();
    height_m_ = height_m;
  }

  // the command's rpy_des and pos_des x, y as the pose; height_m as the height; true when a value
  // was outside its range (and held at its edge)
  template <typename Ranges>
  bool set(const HighLevelCommand& command, double height_m, const Ranges& ranges) {
    return place(rpy_of(command), offset_of(command), height_m, ranges);
  }
  // the command's rpy_des, pos_des x, y added to the pose, and height_change_m to the height
  template <typename Ranges>
  bool add(const HighLevelCommand& command, double height_change_m, const Ranges& ranges) {
    return place(rpy_des_ + rpy_of(command), offset_m_ + offset_of(command), height_m_ + height_change_m, ranges);
  }

  // as the command states it (+pitch: head up)
  const Eigen::Vector3d& rpy_des() const { return rpy_des_; }
  // as the body's attitude (right-handed ZYX)
  Eigen::Vector3d body_rpy() const { return body_rpy_from_command(rpy_des_); }
  const Eigen::Vector2d& offset_m() const { return offset_m_; }
  double height_m() const { return height_m_; }

 private:
  static Eigen::Vector3d rpy_of(const HighLevelCommand& c) { return {c.rpy_des[0], c.rpy_des[1], c.rpy_des[2]}; }
  static Eigen::Vector2d offset_of(const HighLevelCommand& c) { return {c.pos_des[0], c.pos_des[1]}; }

  template <typename Ranges>
  bool place(const Eigen::Vector3d& rpy, const Eigen::Vector2d& offset, double height_m, const Ranges& ranges) {
    rpy_des_ = {ranges.roll.clamp(rpy.x()), ranges.pitch.clamp(rpy.y()), ranges.yaw.clamp(rpy.z())};
    offset_m_ = {ranges.offset_x.clamp(offset.x()), ranges.offset_y.clamp(offset.y())};
    height_m_ = ranges.height.clamp(height_m);
    // a difference of float rounding is no clamp
    constexpr double kTolerance = 1e-6;
    return (rpy_des_ - rpy).cwiseAbs().maxCoeff() > kTolerance ||
           (offset_m_ - offset).cwiseAbs().maxCoeff() > kTolerance || std::abs(height_m_ - height_m) > kTolerance;
  }

  Eigen::Vector3d rpy_des_ = Eigen::Vector3d::Zero();
  Eigen::Vector2d offset_m_ = Eigen::Vector2d::Zero();
  double height_m_ = kDefaultBodyHeightM;
};

}  // namespace cerebellum
