// The MC's state feedback shared by both CyberDog2 interfaces: state_estimator (trunk) and
// leg_control_data (joints in wire convention, feet in the hip frame).
#pragma once

#include <array>
#include <cstdint>

#include "core/robot_readings.hpp"
#include "core/robot_state.hpp"
#include "core/types.hpp"
#include "leg_control_data_lcmt.hpp"
#include "state_estimator_lcmt.hpp"

namespace cerebellum {

inline constexpr const char* kStateEstimatorChannel = "state_estimator";

// p, vWorld, vBody (and their _abs copies: the estimate is the only one), rpy, omegaBody,
// omegaWorld, quat (w, x, y, z), aBody, aWorld (the IMU's specific force, gravity included: body
// frame and turned into the world; the motor SDK's RobotData.acc is aWorld), contactEstimate;
// timestamp in ns of robot time
state_estimator_lcmt make_state_estimator(const RobotState& state);

// the IMU as a robot's state_estimator carries it: quat (w, x, y, z), omegaBody (rad/s), aBody
// (the specific force, body frame, m/s^2): what the motor SDK robot backend reads as its IMU
ImuReading imu_from_state_estimator(const state_estimator_lcmt& message);

// q, qd, tau_est in wire convention; p, v = foot position and velocity in the hip frame;
// force_est = J^-T tau (the force the foot pushes with; the ground's reaction is its negative);
// force_desired = J^-T tau_ff of the command; zero where the leg is singular
leg_control_data_lcmt make_leg_control_data(const RobotState& state, const JointCommand& command);

}  // namespace cerebellum
