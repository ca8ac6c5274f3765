// A reader on another thread never gets a torn state frame: the MC publishes frames back to back
// as fast as it can (far faster than 1 kHz, so most reads overlap a rewrite) and every frame the
// reader accepts must be one frame, whole.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <thread>

#include "io/shm_lowlevel/shm_lowlevel_port.hpp"
#include "io/shm_lowlevel/shm_test_client.hpp"
#include "io/shm_lowlevel/shm_test_names.hpp"

namespace cerebellum {
namespace {

// every number of frame k is k (the quaternion's w is -k), its time k ms
SensorFrame uniform_frame(int k) {
  SensorFrame frame;
  const double v = static_cast<double>(k);
  frame.time_s = 0.001 * v;
  frame.q.fill(v);
  frame.qd.fill(v);
  frame.tau.fill(v);
  frame.temperature_c.fill(25.0);
  frame.imu_quat = {-v, v, v, v};
  frame.imu_gyro = {v, v, v};
  frame.imu_accel = {v, v, v};
  return frame;
}

// the frame number if every field agrees, else -1
int frame_number(const leg_state_t (&legs)[4], const nav_imu_t& imu) {
  const float k = legs[0].abad.p;
  for (const leg_state_t& leg : legs) {
    const joint_state_t joints[3] = {leg.abad, leg.hip, leg.knee};
    for (const joint_state_t& j : joints) {
      if (j.p != k || j.v != k || j.t != k) return -1;
    }
  }
  if (imu.q[0] != -k || imu.q[1] != k || imu.q[2] != k || imu.q[3] != k) return -1;
  for (int i = 0; i < 3; ++i) {
    if (imu.acc[i] != k || imu.gyro[i] != k) return -1;
  }
  if (imu.timestamp != static_cast<std::size_t>(k) * 1000000u) return -1;
  return static_cast<int>(k);
}

TEST(ShmTornFrame, ReaderAcceptsOnlyWholeFrames) {
  ShmLowLevelConfig config;
  config.enabled = true;
  config.name_prefix = unique_shm_prefix();
  std::FILE* log = std::tmpfile();
  ASSERT_NE(log, nullptr);
  {
    ShmLowLevelPort port(config, GuardLimits{}, log);
    ShmTestClient client(port.spline_object_name(), port.imu_object_name());
    constexpr int kFrames = 200000;
    std::atomic<bool> writing{true};
    std::thread writer([&] {
      JointCommand command;
      for (int k = 1; k <= kFrames; ++k) port.on_substep(uniform_frame(k), command);
      writing.store(false);
    });

    int accepted = 0;
    int torn = 0;
    int out_of_order = 0;
    int newest = 0;
    leg_state_t legs[4];
    nav_imu_t imu{};
    const auto read_one = [&] {
      if (!lowlevel_read_state(client.shm(), client.imu(), CONSUMER_CONTROL, legs, &imu)) return false;
      const int k = frame_number(legs, imu);
      if (k < 0) {
        ++torn;
      } else if (k <= newest) {
        ++out_of_order;
      } else {
        newest = k;
      }
      ++accepted;
      return true;
    };
    while (writing.load()) read_one();
    writer.join();
    // a frame published while nobody writes reads whole at once (a read racing a publish may
    // have cleared the flag of the last frame above: the vendor handshake can skip a frame)
    JointCommand command;
    port.on_substep(uniform_frame(kFrames + 1), command);
    EXPECT_TRUE(read_one());
    EXPECT_EQ(torn, 0) << "of " << accepted << " accepted frames";
    EXPECT_EQ(out_of_order, 0);
    EXPECT_EQ(newest, kFrames + 1);
  }
  std::fclose(log);
}

}  // namespace
}  // namespace cerebellum
