// The ranges the high-level modes clamp their command fields to (docs/modes.md lists them with
// their sources), and the decoding of the contact bits and the lifted foot's offset.
#pragma once

#include <array>

#include <Eigen/Core>

#include "control/locomotion/gait_table.hpp"

#include "core/robot_model.hpp"
#include "core/high_level_command.hpp"

namespace cerebellum {

struct Range {
  double lower;
  double upper;
  double clamp(double value) const;
};

// the body height of the standing modes when a command gives none (pos_des[2] <= 0)
inline constexpr double kDefaultBodyHeightM = robot::kStandHeightM;

// mode 3 (QP stand): roll, pitch absolute, yaw relative; x, y offsets; height absolute
struct QpStandRanges {
  Range roll{-0.52, 0.52};
  Range pitch{-0.25, 0.3};
  Range yaw{-0.65, 0.65};
  Range offset_x{-0.05, 0.05};
  Range offset_y{-0.05, 0.05};
  Range height{0.15, 0.32};
  double default_height_m = kDefaultBodyHeightM;
};

// mode 21 (pose control): gait 0 pose about the stand pose, gait 5 absolute height
struct PoseControlRanges {
  Range roll{-0.45, 0.45};
  Range pitch{-0.45, 0.45};
  Range yaw{-0.45, 0.45};
  Range offset_x{-0.08, 0.08};
  Range offset_y{-0.06, 0.06};
  Range height{0.15, 0.27};     // gait 5, and base height + z offset of gait 0
  Range ctrl_point{-0.3, 0.3};  // each axis, body frame
  double default_height_m = kDefaultBodyHeightM;
};

// mode 11 stand gaits (1, 31): pitch and height
struct LocomotionStandRanges {
  Range pitch{-0.25, 0.3};
  Range height{0.2, 0.28};
  double default_height_m = kDefaultBodyHeightM;
};

// a user gait's steps (gait 110): pose and swing heights as decoded from the uploaded parameters
struct UserGaitRanges {
  Range roll{-0.3, 0.3};
  Range pitch = LocomotionStandRanges{}.pitch;
  Range yaw_offset{-0.3, 0.3};
  Range height = LocomotionStandRanges{}.height;  // 0 in the file: the default height
  Range step_height{0.0, 0.10};                   // packed in mm, up to 999 on the wire
  Range landing_gain{0.01, 10.0};                 // outside: 1.0 (reference)
  Range friction{0.1, 1.0};                       // outside: the MPC's own (reference: "sane range")
  // body_pos_des x, y (pos_des[0:2]) of a step without velocity on that axis: the trunk's reach over
  // planted feet (mode 21's), as a step may keep every foot down while the trunk moves
  Range offset_x = PoseControlRanges{}.offset_x;
  Range offset_y = PoseControlRanges{}.offset_y;
  // |vel_des| below this on an axis (m/s) is no velocity there: under 1 mm per second of travel
  double no_velocity_m_s = 1e-3;
};

// mode 11 velocity limits of a gait (gait table; clamped, not rejected)
struct VelocityLimits {
  Eigen::Vector3d min;  // vx, vy (m/s), yaw rate (rad/s)
  Eigen::Vector3d max;
};
// mode 11 swing height, front and rear: the reference's 0..0.06 m with a floor of 5 mm (a documented
// clamp, docs/locomotion.md): a trot 3 at 0.3 m/s for 4 s after a stand covers 1.14 m at 60 mm,
// 1.07 m at 5 mm, 1.04 m at 4 mm, 0.84 m at 3 mm, 0.32 m at 2 mm and 0.16 m at 0 or 1 mm, where
// the swing feet (their apex tracks some 2.5 mm below the target) scuff the ground
inline constexpr Range kStepHeightRange{0.005, 0.06};

// the widest an MC configured beyond the product (section locomotion_limits:) may set: past these
// the values are no limits a controller of this robot could honour, so a file asking more is
// refused. Forward/backward, lateral (m/s), yaw rate (rad/s); swing height (m, under the hip: the
// leg is 0.4 m long and stands at 0.25 m)
inline constexpr double kExtendedForwardSpeedCeilingMPerS = 3.5;
inline constexpr double kExtendedLateralSpeedCeilingMPerS = 1.0;
inline constexpr double kExtendedYawRateCeilingRadPerS = 4.0;
inline constexpr double kExtendedStepHeightCeilingM = 0.15;

// what mode 11 clamps a command's velocity and swing height to: the product's (the gait table's
// and kStepHeightRange) by default; config/extended.yaml widens them (docs/locomotion.md, "Beyond
// the product")
class LocomotionLimits {
 public:
  LocomotionLimits();  // the product's
  // nullptr for gaits without velocity limits (stand gaits, user gaits, unknown ids)
  const VelocityLimits* velocity(int gait_id) const;
  // replaces a stepping gait's limits; false (and no change) for a gait without
  bool set_velocity(int gait_id, const VelocityLimits& limits);
  const Range& step_height() const { return step_height_; }
  void set_step_height(const Range& range) { step_height_ = range; }

 private:
  std::array<VelocityLimits, kGaitTable.size()> velocity_;
  Range step_height_ = kStepHeightRange;
};

// the lifted foot's offset from its foothold (front legs: foot_pose[0..2], rear: [3..5])
struct FootOffsetRanges {
  Range x{-0.15, 0.15};
  Range y{-0.10, 0.10};
  Range z{0.0, 0.20};
  double default_lift_m = 0.08;  // straight up when the offset is all zero
};

// contact bits (bit i: leg i on the ground): the single leg to lift, kNoLiftedLeg when all four
// stay down (0x0F, or 0 as sent by clients that leave the field unset), kInvalidContact otherwise
inline constexpr int kNoLiftedLeg = -1;
inline constexpr int kInvalidContact = -2;
int lifted_leg_from_contact(int contact);

Eigen::Vector3d lifted_foot_offset(const HighLevelCommand& command, int leg, const FootOffsetRanges& ranges = {});

}  // namespace cerebellum
