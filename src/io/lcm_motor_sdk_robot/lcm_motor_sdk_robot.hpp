// The CyberDog2 as the MC's robot, through the vendor's motor SDK over LCM: the MC is the motor SDK
// client. The backend's thread receives spi_data, motor_ctrl_state and state_estimator (checked,
// decoded, stamped on the link's clock) and publishes the motor_ctrl frames the loop queued; the
// loop thread applies the client's rules (MotorSdkClient) and only copies through rings. Paced by
// the wall clock: advance() returns at once, the loop's pacing makes real time.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "backend/hardware_backend.hpp"
#include "core/spsc_ring.hpp"
#include "io/common/adapter_thread.hpp"
#include "io/common/count.hpp"
#include "io/common/count_report.hpp"
#include "io/common/rate_limited_log.hpp"
#include "io/robot_link/listening_window.hpp"
#include "io/lcm_motor_sdk_robot/motor_sdk_client.hpp"
#include "motor_ctrl_lcmt.hpp"

namespace lcm {
class LCM;
struct ReceiveBuffer;
}  // namespace lcm

namespace cerebellum {

// packets from the robot that never reached the MC
struct MotorSdkRobotRejections {
  Count malformed;   // wrong fingerprint, truncated, oversized
  Count non_finite;  // NaN or Inf in a joint or IMU value
  Count dropped;     // the loop had not taken the previous ones (it stopped or stalls)
};

class LcmMotorSdkRobot final : public HardwareBackend {
 public:
  // opens both urls and starts the thread; throws std::runtime_error naming a url LCM cannot
  // open. log: where the link's events go (written by the backend's thread only)
  LcmMotorSdkRobot(const MotorSdkRobotConfig& config, std::FILE* log);
  ~LcmMotorSdkRobot() override;
  LcmMotorSdkRobot(const LcmMotorSdkRobot&) = delete;
  LcmMotorSdkRobot& operator=(const LcmMotorSdkRobot&) = delete;

  SensorFrame read() override;
  void write(const JointCommand& command) override;
  void advance(double period_s) override { robot_time_s_ += period_s; }
  double time_s() const override { return robot_time_s_; }
  RobotLinkReport link_report() const override;

  // HardwareBackend. activate: all-zero frames at 500 Hz until the robot answers in motor mode
  // without err_flag bit 1; false when config.activation_timeout_s passes or stop is set
  bool activate(const std::atomic<bool>& stop) override;
  std::string activation_text() const override;
  std::string activation_failure() const override;
  std::string description() const override;
  // stops the thread and prints one summary line
  void finish(std::FILE* out) override;
  MotorSdkRobotRejections rejections() const { return rejected_; }

 private:
  struct Joints {
    JointReading state;
    double received_s = 0.0;
  };
  struct Imu {
    ImuReading sample;
    double received_s = 0.0;
  };
  struct StatusAt {
    MotorSdkClientStatus status;
    double robot_time_s = 0.0;
  };

  void step();
  void on_spi_data(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void on_state_estimator(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void on_ctrl_state(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void log_changes(const StatusAt& now);
  void log_counts_once_per_second();

  MotorSdkRobotConfig config_;
  std::FILE* log_;
  std::unique_ptr<lcm::LCM> control_lcm_;
  std::unique_ptr<lcm::LCM> estimator_lcm_;
  // the backend's thread -> the loop
  SpscRing<Joints, 32> joints_;
  SpscRing<Imu, 32> imu_;
  SpscRing<std::uint16_t, 32> err_flags_;
  // the loop -> the backend's thread
  SpscRing<motor_ctrl_lcmt, 32> frames_;
  SpscRing<StatusAt, 64> statuses_;
  MotorSdkRobotRejections rejected_;
  // loop thread only
  MotorSdkClient client_;
  double robot_time_s_ = 0.0;
  // the backend's thread steps it, the loop thread reads its window (wall seconds)
  ListeningClock listening_;
  // backend's thread only
  StatusAt logged_;
  RateLimitedLog link_log_;
  std::uint64_t counts_logged_ = 0;
  EveryPeriod count_log_period_;
  // last member: started once everything above is built, stopped first
  AdapterThread thread_;
};

}  // namespace cerebellum
