// Physical constants of the CyberDog2-class body (reference: robot-cyberdog2.md), SDK convention.
#pragma once

#include <array>
#include <cmath>

#include "core/joint_layout.hpp"

namespace cerebellum::robot {

inline constexpr double kPi = 3.14159265358979323846;
constexpr double deg(double degrees) { return degrees * kPi / 180.0; }

// standard gravity (m/s^2), the figure every controller, estimator and simulated IMU uses
inline constexpr double kGravityMPerS2 = 9.81;

// geometry (m)
inline constexpr double kHipX = 0.164;        // abad joint, body frame, +-x
inline constexpr double kHipY = 0.042;        // abad joint, body frame, +-y
inline constexpr double kAbadLength = 0.094;  // lateral offset from abad axis to thigh
inline constexpr double kThighLength = 0.12;
inline constexpr double kShankLength = 0.17391;
inline constexpr double kFootRadius = 0.019;
// the IMU's place in the body frame (m): its accelerometer also feels the trunk's rotation there
inline constexpr double kImuPositionBody[3] = {0.0334, -0.0173, 0.0510};

// joint ranges (rad), SDK convention
struct JointRange {
  double lower;
  double upper;
};
inline constexpr JointRange kAbadRange{-0.68, 0.68};
inline constexpr JointRange kFrontHipRange{-1.33, 2.79};
inline constexpr JointRange kRearHipRange{-0.98, 3.14};
inline constexpr JointRange kKneeRange{-2.53, -0.52};

constexpr JointRange joint_range(std::size_t index) {
  const std::size_t leg = index / kJointsPerLeg;
  switch (index % kJointsPerLeg) {
    case 0: return kAbadRange;
    case 1: return is_front_leg(leg) ? kFrontHipRange : kRearHipRange;
    default: return kKneeRange;
  }
}

// actuators
inline constexpr double kGearRatio = 7.75;
inline constexpr double kTorqueMaxNm = 12.0;
inline constexpr double kFullTorqueSpeedRadS = 11.52;  // joint side; full torque below this
inline constexpr double kNoLoadSpeedRadS = 30.5;       // joint side; motoring torque falls to 0 here
inline constexpr double kMotorKt = 0.05;               // N m / A, motor side
inline constexpr double kMotorResistanceOhm = 0.173;
// motor coil temperatures (robot-cyberdog2.md): the driver warns, then stops
inline constexpr double kMotorWarningTemperatureC = 82.0;
inline constexpr double kMotorShutdownTemperatureC = 87.0;

// battery (robot-cyberdog2.md: 21.6 V pack, 4500 mAh, 97.2 Wh): six lithium-ion cells in series.
// The reference gives no internal resistance, idle load or driver voltage limits: the figures
// marked "assumed" are typical of such a pack and board (docs/safety.md)
inline constexpr int kBatteryCells = 6;
inline constexpr double kBatteryCapacityAh = 4.5;
// assumed: 6 high-drain cells of 10 mOhm. The robot jumps and flips from this pack: a push draws
// 60-80 A, which a 0.12 ohm pack (20 mOhm cells) would sag below the drivers' 18 V cut-off
inline constexpr double kBatteryInternalResistanceOhm = 0.06;
inline constexpr double kIdleElectricalPowerW = 25.0;     // assumed: boards, sensors, fans

// the air around the robot, where every simulated part starts and cools to
inline constexpr double kAmbientTemperatureC = 25.0;
// assumed: the IMU sits on the main board inside the trunk and its temperature sensor reads the
// board, which the idle power warms 15 K above the ambient with a 5 min time constant
inline constexpr double kMainBoardThermalResistanceKPerW = 0.6;
inline constexpr double kMainBoardHeatCapacityJPerK = 500.0;
inline constexpr double kDriverUnderVoltageV = 18.0;      // assumed: 3.0 V per cell
inline constexpr double kDriverOverVoltageV = 26.0;       // assumed: above a full pack's 25.2 V
inline constexpr double kDriverVoltageHysteresisV = 0.5;  // assumed: a tripped limit clears this far inside
// assumed: the drivers' bus capacitors and trip debounce; a millisecond current spike of a
// landing does not trip them, a sagging pack does
inline constexpr double kDriverBusFilterS = 0.02;

// the joint damping (N m s/rad) of every damping command the MC gives by itself: PureDamper, the
// guard's replacement command, a lost low-level link, a failed solve, a failed jump or two-leg stand
inline constexpr double kDampingKd = 4.0;

// whole-body figures the controllers use
inline constexpr double kTotalMassKg = 8.52;  // body + legs + rotors of the MJCF model
// the convex MPC's lumped mass and inertia: the model the gaits and the soak were tuned with, not
// a second figure of the body's mass (kTotalMassKg is that); a change needs a new soak
inline constexpr double kMpcMassKg = 8.3644;
inline constexpr std::array<double, 3> kMpcInertiaDiag{0.07641, 0.17843, 0.197579};

// leg links as published for a right leg (left legs mirror y): mass and centre of mass in the
// link's joint frame; the rotors are point masses on the link axis
struct LinkMass {
  double mass_kg;
  std::array<double, 3> com_m;
  // about the centre of mass: link x (the abad joint's axis) and y (the pitch joints' axis)
  double inertia_xx_kg_m2;
  double inertia_yy_kg_m2;
};
inline constexpr LinkMass kBodyLink{4.03, {0.0273, -0.000242, 0.0143}, 0.0185, 0.0517};  // the trunk
inline constexpr LinkMass kAbadLink{0.354, {-0.00392, -0.015, -0.000306}, 0.00019, 0.000276};
inline constexpr LinkMass kThighLink{0.482, {0.00212, -0.0212, -0.0184}, 0.00101, 0.000983};
inline constexpr LinkMass kShankLink{0.116, {-0.0006, 4.72e-5, -0.0893}, 0.000668, 0.000674};
inline constexpr double kRotorMassKg = 0.0567;
inline constexpr double kAbadRotorX = 0.0998;        // the abad rotors sit on the trunk: +-x, on the abad axis
inline constexpr double kHipRotorOffsetM = 0.0758;   // along the abad link, from the abad joint
inline constexpr double kKneeRotorOffsetM = 0.0342;  // along the thigh, from the hip joint
// a rotor's inertia about its own axis and across it (the model file's rotor bodies)
inline constexpr double kRotorAxialInertiaKgM2 = 4.78e-5;
inline constexpr double kRotorCrossInertiaKgM2 = 2.53e-5;
// the rotor's spin seen at the joint through the gear, 4.78e-5 x 7.75^2 rounded as the model
// file's armature="0.00287" has it (the simulated joints carry this figure)
inline constexpr double kJointArmatureKgM2 = 0.00287;

// the trunk's height above the ground in the default stand (cyberdog2-highlevel.md: mode 3's
// default height)
inline constexpr double kStandHeightM = 0.235;
// the trunk's height while walking, unless a command asks another: the gaits were tuned at it
inline constexpr double kWalkHeightM = 0.25;

// default poses per leg (abad, hip, knee), SDK convention
inline constexpr std::array<double, 3> kStandPose{0.0, deg(45.0), deg(-70.0)};
inline constexpr std::array<double, 3> kLyingPose{0.0, deg(80.0), deg(-135.0)};

inline JointArray<double> whole_body_pose(const std::array<double, 3>& leg_pose) {
  JointArray<double> q{};
  for (std::size_t i = 0; i < kNumJoints; ++i) q[i] = leg_pose[i % kJointsPerLeg];
  return q;
}

// safety stage: the interface's foot workspace and command ranges
// (cyberdog2-highlevel.md, cyberdog2-lowlevel.md section 5)
// "L = 0.294 m": the interface's leg length to the foot contact (thigh + shank is 0.29391 m)
inline constexpr double kInterfaceLegLengthM = 0.294;
// motor command ranges: "qd_des -12..12 rad/s, kp 0..200, kd 0..10, tau_des -12..12 Nm"
inline constexpr double kCommandKpMax = 200.0;
inline constexpr double kCommandKdMax = 10.0;
inline constexpr double kCommandQdDesMaxRadS = 12.0;

}  // namespace cerebellum::robot
