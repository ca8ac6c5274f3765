// cyber_dog_motor_sdk: the CyberDog2 low-level motor SDK client (the official API: an unmodified
// user program compiles and runs against it). Subclass CustomInterface, write UserCode, Spin().
//
// Joint order FR, FL, RR, RL x (abad, hip, knee); angles in the SDK / URDF convention. The library
// flips hip and knee to and from the MC's wire convention.
#pragma once

// what the official header pulls in, so an unmodified program that includes only this header
// compiles (the seed's example uses signal, SIGINT and std::make_shared without including them)
#include <assert.h>
#include <lcm/lcm-cpp.hpp>
#include <signal.h>
#include <sys/mman.h>
#include <sys/timerfd.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <iostream>
#include <memory>
#include <string>
#include <thread>

#include "leg_control_data_lcmt.hpp"
#include "motor_ctrl_lcmt.hpp"
#include "motor_ctrl_state_lcmt.hpp"
#include "spi_data_t.hpp"
#include "state_estimator_lcmt.hpp"

struct RobotData {
  float q[12];                // joint angles, rad
  float qd[12];               // joint velocities, rad/s
  float tau[12];              // joint torques, N m
  float quat[4];              // trunk orientation (w, x, y, z)
  float rpy[3];               // roll, pitch, yaw, rad
  float acc[3];               // IMU specific force (gravity included: +9.81 on z at rest), world frame, m/s^2
  float omega[3];             // trunk angular velocity, world frame, rad/s
  float ctrl_topic_interval;  // ms between the MC's last two received commands
  uint32_t motor_flags[12];   // per motor: mode bits 30..31, error and warning bits below
  int16_t err_flag;           // motor_ctrl_state.err_flag (bit1: activate with all-zero frames)
};

// each motor runs tau = tau_des + kp_des (q_des - q) + kd_des (qd_des - qd)
struct MotorCmd {
  float q_des[12];    // rad
  float qd_des[12];   // rad/s, -12..12
  float kp_des[12];   // 0..200
  float kd_des[12];   // 0..10
  float tau_des[12];  // N m, -12..12
};

class CustomInterface {
 public:
  // loop_rate in Hz; <= 0 means 500
  CustomInterface(const double& loop_rate);
  virtual ~CustomInterface();
  CustomInterface(const CustomInterface&) = delete;
  CustomInterface& operator=(const CustomInterface&) = delete;

  // runs UserCode at the loop rate and sends motor_cmd_ until Stop(); blocks
  void Spin();
  // safe to call from a signal handler or from UserCode
  void Stop();
  void Zero_Cmd(MotorCmd& cmd);
  void PrintData(RobotData& data);

 protected:
  // every tick; first_run stays true while the MC reports err_flag bit1 (the command is then
  // replaced by all-zero frames, which activate motor mode and clear the error)
  virtual void UserCode(bool first_run) = 0;

  RobotData robot_data_;
  MotorCmd motor_cmd_;

 private:
  class Channels;
  void Tick();

  double loop_rate_hz_;
  bool first_run_ = true;
  std::atomic<bool> stop_requested_{false};
  std::unique_ptr<Channels> channels_;
};
