// A low-level client for tests: maps the MC's objects through lowlevel.h and talks through the
// lowlevel_sync.h helpers, as a user program would.
#pragma once

#include <sys/mman.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <string>

#include "core/joint_layout.hpp"
#include "lowlevel/lowlevel.h"
#include "lowlevel/lowlevel_sync.h"

namespace cerebellum {

class ShmTestClient {
 public:
  ShmTestClient(const std::string& spline_name, const std::string& imu_name)
      : shm_(create_spline_shm_named(spline_name.c_str())), imu_(create_imu_shm_named(imu_name.c_str())) {}
  ~ShmTestClient() {
    ::munmap(shm_, LOWLEVEL_SPLINE_SHM_SIZE);
    ::munmap(imu_, LOWLEVEL_IMU_SHM_SIZE);
  }
  ShmTestClient(const ShmTestClient&) = delete;
  ShmTestClient& operator=(const ShmTestClient&) = delete;

  // a new whole frame since the last call: joint positions (SDK order) and the IMU
  bool read_state(JointArray<double>& q, nav_imu_t* imu_out = nullptr) {
    leg_state_t legs[4];
    nav_imu_t imu{};
    if (!lowlevel_read_state(shm_, imu_, CONSUMER_CONTROL, legs, &imu)) return false;
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      q[joint_index(leg, 0)] = legs[leg].abad.p;
      q[joint_index(leg, 1)] = legs[leg].hip.p;
      q[joint_index(leg, 2)] = legs[leg].knee.p;
    }
    if (imu_out != nullptr) *imu_out = imu;
    return true;
  }

  // every joint at its q_des with the same gains; false when the MC has not taken the last frame
  bool send(const JointArray<double>& q_des, float kp, float kd) {
    leg_control_t legs[4];
    position_frame(q_des, kp, kd, legs);
    return lowlevel_write_command(shm_, legs);
  }

  static void position_frame(const JointArray<double>& q_des, float kp, float kd, leg_control_t (&legs)[4]) {
    std::memset(legs, 0, sizeof(legs));
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      joint_control_t* joints[3] = {&legs[leg].abad, &legs[leg].hip, &legs[leg].knee};
      for (std::size_t j = 0; j < 3; ++j) {
        joints[j]->p_des = static_cast<float>(q_des[joint_index(leg, j)]);
        joints[j]->kp = kp;
        joints[j]->kd = kd;
      }
      legs[leg].flags = 1;
    }
  }

  bool send_raw(const leg_control_t (&legs)[4]) { return lowlevel_write_command(shm_, legs); }

  spline_data_p shm() const { return shm_; }
  nav_imu_p imu() const { return imu_; }
  std::uint32_t state_flag(lowlevel_consumer_t consumer) const {
    return __atomic_load_n(lowlevel_state_flag(shm_, consumer), __ATOMIC_ACQUIRE);
  }
  std::uint32_t command_flag() const { return __atomic_load_n(lowlevel_command_flag(shm_), __ATOMIC_ACQUIRE); }

 private:
  spline_data_p shm_;
  nav_imu_p imu_;
};

}  // namespace cerebellum
