#include "io/lcm_motor_sdk_robot/motor_sdk_client.hpp"

#include "lowlevel/motor_sdk/motor_sdk_frame_rules.hpp"
#include "safety/damping_command.hpp"

namespace cerebellum {

MotorSdkClient::MotorSdkClient(const MotorSdkRobotConfig& config)
    : config_(config), watch_(config.link_timeout_s) {}

void MotorSdkClient::take_joints(const JointReading& joints, double received_s) {
  watch_.take_joints(joints, received_s);
  take_watch_status();
}

void MotorSdkClient::take_imu(const ImuReading& imu, double received_s) {
  watch_.take_imu(imu, received_s);
  take_watch_status();
}

void MotorSdkClient::take_err_flag(std::uint16_t err_flag) {
  status_.err_flag = err_flag;
  // bit 1: the robot has lost (or never had) our frames and damps; it takes commands again only
  // after all-zero frames, so the client sends those while the bit is set
  status_.activated = (err_flag & kMotorSdkCommandLost) == 0;
  if (err_flag & kMotorSdkCommandLate) ++status_.late_reports;
  if (err_flag & (kMotorSdkAbadJump | kMotorSdkHipJump | kMotorSdkKneeJump)) ++status_.jump_reports;
}

SensorFrame MotorSdkClient::frame(const ListeningWindow& window, double robot_time_s) {
  SensorFrame frame = watch_.frame(window, robot_time_s);
  take_watch_status();
  return frame;
}

JointCommand MotorSdkClient::command(const JointCommand& mc_command) {
  if (status_.stopped) return damping_command(config_.motor_error_damping_kd, watch_.q());
  if (!status_.activated) {
    ++status_.zero_frames;
    return passive_command();
  }
  JointCommand frame = mc_command;
  const RangeClampCount ranges = clamp_to_ranges(frame, config_.rules);
  if (ranges.gains + ranges.velocities + ranges.torques + ranges.positions > 0) ++status_.range_clamps;
  if (config_.rules.position_mutation_limit && clamp_position_jumps(frame, watch_.q(), config_.rules).joints > 0) {
    ++status_.jump_clamps;
  }
  return frame;
}

}  // namespace cerebellum
