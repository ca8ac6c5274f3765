// The IMU's temperature (AlienGo HighState.imu.temperature) is the IMU's own sensor: the main
// board it sits on, warmed by the boards' idle power from the ambient, not a motor's coil. The
// whole MC in lockstep on the simulated robot, the field read through the vendor's struct, judged
// on the first-order law solved here from the robot's figures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "backend/sim_fixture.hpp"
#include "core/robot_model.hpp"
#include "io/udp_aliengo/aliengo_wire.hpp"
#include "loop/lockstep_client.hpp"
#include "loop/simulated_robot.hpp"
#include "unitree_legged_sdk/comm.h"

namespace cerebellum {
namespace {

int wire_imu_temperature_c(const CycleRecord& record) {
  std::uint8_t bytes[kHighStateBytes];
  encode_high_state(make_feedback(record.state, 0), bytes);
  return static_cast<std::int8_t>(
      bytes[offsetof(UNITREE_LEGGED_SDK::HighState, imu) + offsetof(UNITREE_LEGGED_SDK::IMU, temperature)]);
}

// the board after t_s of idle power from the ambient: T = ambient + P R (1 - exp(-t / (R C)))
double board_temperature_c(double t_s) {
  const double rise_k = robot::kIdleElectricalPowerW * robot::kMainBoardThermalResistanceKPerW;
  const double time_constant_s = robot::kMainBoardThermalResistanceKPerW * robot::kMainBoardHeatCapacityJPerK;
  return robot::kAmbientTemperatureC + rise_k * (1.0 - std::exp(-t_s / time_constant_s));
}

TEST(ImuTemperature, TheAlienGoImuTemperatureIsTheWarmingMainBoardNotTheCoolestMotor) {
  McConfig config = default_config();
  config.startup = Startup::Off;
  Mc mc = make_simulated_mc(config);
  LockstepClient client(mc);
  HighLevelCommand off;  // lying switched off: the motors carry no current and stay at the ambient
  int first_c = -1000;
  client.run(off, 0.01, [&](const CycleRecord& record) {
    if (first_c == -1000) first_c = wire_imu_temperature_c(record);
  });
  EXPECT_EQ(first_c, static_cast<int>(std::lround(board_temperature_c(0.0))));

  int last_c = 0;
  double coolest_motor_c = 0.0, time_s = 0.0;
  client.run(off, 90.0, [&](const CycleRecord& record) {
    last_c = wire_imu_temperature_c(record);
    coolest_motor_c = *std::min_element(record.state.temperature_c.begin(), record.state.temperature_c.end());
    time_s = record.state.time_s;
  });
  EXPECT_EQ(last_c, static_cast<int>(std::lround(board_temperature_c(time_s))));
  // the board has warmed by whole degrees while the motors have not: the field is not a motor's
  EXPECT_GE(last_c - first_c, 3);
  EXPECT_NE(last_c, static_cast<int>(std::lround(coolest_motor_c)));
}

}  // namespace
}  // namespace cerebellum
