// Telemetry rows: attitude from the simulator's quaternion, truth velocity in the body frame,
// and the CSV header and lines agreeing column by column.
#include "observers/record_telemetry.hpp"
#include "observers/viewer_snapshot.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <sstream>

namespace cerebellum {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) fields.push_back(field);
  return fields;
}

std::array<double, 4> quat_from_rpy(double roll, double pitch, double yaw) {
  const Eigen::Quaterniond q = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX());
  return {q.w(), q.x(), q.y(), q.z()};
}

TEST(TelemetryRow, TruthAttitudeIsTheRollPitchYawOfTheSimulatorQuaternion) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-3.0, 3.0);
  std::uniform_real_distribution<double> pitch_angle(-1.5, 1.5);
  for (int i = 0; i < 50; ++i) {
    const double roll = angle(rng);
    const double pitch = pitch_angle(rng);
    const double yaw = angle(rng);
    GroundTruth truth;
    truth.quat = quat_from_rpy(roll, pitch, yaw);
    const TelemetryRow row = telemetry_row(CycleRecord{}, truth);
    EXPECT_NEAR(row.truth_rpy[0], roll, 1e-9);
    EXPECT_NEAR(row.truth_rpy[1], pitch, 1e-9);
    EXPECT_NEAR(row.truth_rpy[2], yaw, 1e-9);
  }
}

TEST(TelemetryRow, TruthVelocityIsExpressedInTheTrunkFrame) {
  std::mt19937 rng(11);
  std::normal_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 100; ++i) {
    std::array<double, 4> q{unit(rng), unit(rng), unit(rng), unit(rng)};
    const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (double& c : q) c /= norm;
    const std::array<double, 3> v{unit(rng), unit(rng), unit(rng)};
    // the rotation matrix of a unit quaternion, written out: v_body = R^T v_world
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                            {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                            {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    const auto body = planar_velocity_body(q, v, {0.0, 0.0, 0.7});
    EXPECT_NEAR(body[0], r[0][0] * v[0] + r[1][0] * v[1] + r[2][0] * v[2], 1e-12);
    EXPECT_NEAR(body[1], r[0][1] * v[0] + r[1][1] * v[1] + r[2][1] * v[2], 1e-12);
    EXPECT_EQ(body[2], 0.7);
  }
}

TEST(TelemetryRow, CopiesStateTruthAndStatusIntoTheirColumns) {
  CycleRecord record;
  record.tick = 42;
  record.state.time_s = 1.25;
  record.state.velocity_body = {0.4, -0.1, 0.0};
  record.state.omega_body = {0.0, 0.0, 0.3};
  record.state.height_m = 0.26;
  record.state.rpy = {0.01, -0.02, 0.5};
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    record.state.tau[i] = 0.5 * static_cast<double>(i);
    record.state.temperature_c[i] = 30.0 + static_cast<double>(i);
  }
  record.state.battery = {true, 23.5, 3.25, 61.5};
  record.health.causes = kHealthMotorWarning;
  record.health.faulty_motors = 1u << 7;
  GroundTruth truth;
  truth.position = {1.0, 2.0, 0.255};
  truth.quat = quat_from_rpy(0.0, 0.0, M_PI / 2);
  truth.velocity_world = {0.0, 0.5, 0.0};  // along the trunk's x after a quarter turn
  truth.angular_velocity_body = {0.0, 0.0, 0.28};
  HighLevelStatus& status = record.high_level.status;
  status.mode = 11;
  status.gait_id = 3;
  status.switch_status = SwitchStatus::Transitioning;

  HighLevelCommand& running = record.high_level.running_command;
  running.mode = 11;
  running.vel_des = {0.4f, -0.1f, 0.3f};
  const TelemetryRow row = telemetry_row(record, truth);
  const std::vector<std::string> header = split(telemetry_header());
  const std::vector<std::string> fields = split(telemetry_line(row));
  ASSERT_EQ(header.size(), 22u + 2 * kNumJoints + 5);
  ASSERT_EQ(fields.size(), header.size());
  const auto column = [&](const std::string& name) {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (header[i] == name) return std::stod(fields[i]);
    }
    ADD_FAILURE() << "no column " << name;
    return 0.0;
  };
  EXPECT_EQ(column("time_s"), 1.25);
  EXPECT_EQ(column("tick"), 42);
  EXPECT_EQ(column("mode"), 11);
  EXPECT_EQ(column("gait_id"), 3);
  EXPECT_EQ(column("switch_status"), 1);
  EXPECT_NEAR(column("cmd_vx_m_s"), 0.4, 1e-6);
  EXPECT_NEAR(column("cmd_vy_m_s"), -0.1, 1e-6);
  EXPECT_NEAR(column("cmd_wz_rad_s"), 0.3, 1e-6);
  EXPECT_NEAR(column("est_vx_m_s"), 0.4, 1e-6);
  EXPECT_NEAR(column("est_wz_rad_s"), 0.3, 1e-6);
  EXPECT_NEAR(column("est_height_m"), 0.26, 1e-6);
  EXPECT_NEAR(column("est_yaw_rad"), 0.5, 1e-6);
  EXPECT_NEAR(column("truth_vx_m_s"), 0.5, 1e-6);
  EXPECT_NEAR(column("truth_vy_m_s"), 0.0, 1e-6);
  EXPECT_NEAR(column("truth_wz_rad_s"), 0.28, 1e-6);
  EXPECT_NEAR(column("truth_z_m"), 0.255, 1e-6);
  EXPECT_NEAR(column("truth_yaw_rad"), M_PI / 2, 1e-5);
  EXPECT_NEAR(column("tau_fr_abad_nm"), 0.0, 1e-9);
  EXPECT_NEAR(column("tau_rl_knee_nm"), 5.5, 1e-9);
  EXPECT_NEAR(column("temp_fl_hip_c"), 34.0, 1e-9);
  EXPECT_NEAR(column("battery_soc_percent"), 61.5, 1e-9);
  EXPECT_NEAR(column("battery_v"), 23.5, 1e-9);
  EXPECT_NEAR(column("battery_a"), 3.25, 1e-9);
  EXPECT_EQ(column("health_causes"), kHealthMotorWarning);
  EXPECT_EQ(column("faulty_motors"), 128);
}

}  // namespace
}  // namespace cerebellum
