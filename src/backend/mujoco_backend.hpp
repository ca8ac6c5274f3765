// The simulated CyberDog2: MuJoCo physics at 1 kHz with the motor drivers emulated per step.
#pragma once

#include <array>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "backend/motor_model.hpp"
#include "backend/robot_backend.hpp"

struct mjModel_;
struct mjData_;

namespace cerebellum {

struct SensorNoise {
  bool enabled = false;
  unsigned seed = 0;
  double joint_position_rad = 1e-4;
  double joint_velocity_rad_s = 5e-3;
  double gyro_rad_s = 2e-3;
  double accel_m_s2 = 2e-2;
};

struct MujocoBackendConfig {
  std::string model_path;
  std::string initial_keyframe = "lying";  // a <key> of the model
  double initial_height_m = 0.3;           // trunk height at start
  SensorNoise noise;
  MotorLimits motor_limits;
  MotorThermalParameters thermal;
};

// simulator truth, for tests and tools only: never handed to the controller
struct GroundTruth {
  std::array<double, 3> position{};         // world
  std::array<double, 4> quat{1, 0, 0, 0};   // w, x, y, z, body to world
  std::array<double, 3> velocity_world{};
  std::array<double, 3> angular_velocity_body{};
};

class MujocoBackend final : public RobotBackend {
 public:
  // throws std::runtime_error naming the file when the model is missing or broken
  explicit MujocoBackend(const MujocoBackendConfig& config);
  ~MujocoBackend() override;
  MujocoBackend(const MujocoBackend&) = delete;
  MujocoBackend& operator=(const MujocoBackend&) = delete;

  SensorFrame read() override;
  void write(const JointCommand& command) override;
  void advance(double period_s) override;
  double time_s() const override;

  GroundTruth ground_truth() const;
  // place the trunk (tests and tools): position in world, orientation w, x, y, z; zero velocity
  void set_base_pose(const std::array<double, 3>& position, const std::array<double, 4>& quat);
  void set_joint_positions(const JointArray<double>& q);
  // a force on the trunk COM (world frame) that stays until changed, for push tests and the viewer
  void set_external_force(const std::array<double, 3>& force_n);

  double physics_timestep_s() const;
  const mjModel_* model() const { return model_; }
  const mjData_* data() const { return data_; }

 private:
  void apply_motor_drivers();

  MujocoBackendConfig config_;
  mjModel_* model_ = nullptr;
  mjData_* data_ = nullptr;
  JointCommand command_{};
  JointArray<int> qpos_address_{};
  JointArray<int> dof_address_{};
  JointArray<int> actuator_id_{};
  int trunk_body_ = -1;
  int imu_quat_address_ = -1;
  int imu_gyro_address_ = -1;
  int imu_accel_address_ = -1;
  JointArray<double> applied_torque_{};
  bool sensors_stale_ = false;
  std::vector<MotorThermalModel> thermal_;
  std::mt19937 rng_;
  std::normal_distribution<double> unit_normal_{0.0, 1.0};
};

}  // namespace cerebellum
