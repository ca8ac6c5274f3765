#include "io/robot_link/robot_state_watch.hpp"

#include <algorithm>
#include <cmath>

#include "core/robot_model.hpp"

namespace cerebellum {
namespace {

// every value a joint reading carries, as the frame holds the newest one taken
bool same_values(const JointReading& a, const SensorFrame& b) {
  return a.q == b.q && a.qd == b.qd && a.tau == b.tau && a.temperature_c == b.temperature_c &&
         a.motor_faults == b.motor_faults;
}

}  // namespace

double joint_step_limit_rad(double dt_s) {
  return 2.0 * robot::kNoLoadSpeedRadS * std::max(dt_s, 0.0) + robot::deg(5.0);
}

void RobotStateWatch::take_joints(const JointReading& joints, double received_s) {
  // the vendors' clients stop for good on a motor error: a driver that tripped may hold a joint
  // in a state no command of ours can be trusted against. Checked first: an error bit stops us
  // even in a state refused below
  if (!status_.stopped) {
    std::uint32_t error_motors = 0;
    for (std::size_t i = 0; i < kNumJoints; ++i) {
      if (joints.motor_faults[i] & kMotorErrorBits) error_motors |= 1u << i;
    }
    if (error_motors != 0) {
      status_.stopped = true;
      status_.error_motors = error_motors;
    }
  }
  if (have_joints_) {
    if (same_values(joints, frame_)) {
      ++status_.repeated_states;
      return;
    }
    double step_rad = 0.0;
    for (std::size_t i = 0; i < kNumJoints; ++i) step_rad = std::max(step_rad, std::abs(joints.q[i] - frame_.q[i]));
    if (step_rad > joint_step_limit_rad(received_s - joints_received_s_)) {
      ++status_.jumped_states;
      status_.last_jump_rad = step_rad;
      return;
    }
  }
  frame_.q = joints.q;
  frame_.qd = joints.qd;
  frame_.tau = joints.tau;
  frame_.temperature_c = joints.temperature_c;
  frame_.motor_faults = joints.motor_faults;
  frame_.driver_mode = joints.driver_mode;
  have_joints_ = true;
  joints_received_s_ = received_s;
}

void RobotStateWatch::take_imu(const ImuReading& imu, double received_s) {
  if (have_imu_ && imu.quat == frame_.imu_quat && imu.gyro_rad_s == frame_.imu_gyro &&
      imu.specific_force_m_s2 == frame_.imu_accel) {
    ++status_.repeated_states;
    return;
  }
  frame_.imu_quat = imu.quat;
  frame_.imu_gyro = imu.gyro_rad_s;
  frame_.imu_accel = imu.specific_force_m_s2;
  have_imu_ = true;
  imu_received_s_ = received_s;
}

SensorFrame RobotStateWatch::frame(const ListeningWindow& window, double robot_time_s) {
  const bool heard = have_joints_ && have_imu_;
  const double silent_s =
      heard ? std::max(0.0, window.until_s - std::max(std::min(joints_received_s_, imu_received_s_), window.since_s))
            : 0.0;
  // once lost, only a fresh reading brings the link back (a pause of the receiver does not)
  const bool fresh_since_loss = heard && std::min(joints_received_s_, imu_received_s_) > lost_at_s_;
  const bool lost = !heard || silent_s > link_timeout_s_ || (status_.link_lost && !fresh_since_loss);
  if (lost && !status_.link_lost && heard) {
    ++status_.link_losses;
    lost_at_s_ = window.until_s;
  }
  status_.link_lost = lost;
  status_.link_silent_s = silent_s;
  SensorFrame frame = frame_;
  frame.time_s = robot_time_s;
  // a motor whose state stopped coming is, to the MC, a motor that does not answer: the health
  // monitor damps the legs for it, as for any disconnected driver, and lets go once it answers
  if (lost) {
    for (std::uint32_t& faults : frame.motor_faults) faults |= kMotorDisconnected;
  }
  return frame;
}

}  // namespace cerebellum
