// The simulated CyberDog2: MuJoCo physics at 1 kHz with the motor drivers emulated per step.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <random>
#include <string>
#include <vector>

#include "backend/battery_model.hpp"
#include "backend/thermal_mass.hpp"
#include "backend/model_error.hpp"
#include "backend/motor_model.hpp"
#include "backend/push_request.hpp"
#include "backend/robot_backend.hpp"
#include "backend/simulation.hpp"
#include "backend/terrain.hpp"

namespace cerebellum {

struct SensorNoise {
  bool enabled = false;
  unsigned seed = 0;
  double joint_position_rad = 1e-4;
  double joint_velocity_rad_s = 5e-3;
  double gyro_rad_s = 2e-3;
  double accel_m_s2 = 2e-2;
  // every deviation times factor (a noisier robot than the default one)
  void scale(double factor) {
    joint_position_rad *= factor;
    joint_velocity_rad_s *= factor;
    gyro_rad_s *= factor;
    accel_m_s2 *= factor;
  }
};

struct MujocoBackendConfig {
  std::string model_path;
  TerrainSpec terrain;  // the ground built around the model's floor at start (backend/terrain.hpp)
  std::string initial_keyframe = "lying";  // a <key> of the model
  double initial_height_m = 0.3;           // trunk height at start
  SensorNoise noise;
  ModelError model_error;  // the robot's differences from the model (backend/model_error.hpp)
  MotorLimits motor_limits;
  MotorThermalParameters thermal;
  BatteryParameters battery;
  // the main board, where the IMU sits; warmed by the boards' idle power (battery.idle_power_w)
  ThermalMassParameters main_board{robot::kAmbientTemperatureC, robot::kMainBoardThermalResistanceKPerW,
                                   robot::kMainBoardHeatCapacityJPerK};
};

// the MC runs on it as a RobotBackend; tools and tests see it as a Simulation
class MujocoBackend final : public RobotBackend, public Simulation {
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

  GroundTruth ground_truth() const override;
  void set_base_pose(const std::array<double, 3>& position, const std::array<double, 4>& quat) override;
  void set_joint_positions(const JointArray<double>& q) override;
  void set_external_force(const std::array<double, 3>& force_n) override;
  void request_push(const PushRequest& request) override;
  void request_force_pulse(const ForcePulse& pulse) override;
  void set_foot_friction(std::size_t leg, double friction) override;
  void reset_foot_friction(std::size_t leg) override;

  double physics_timestep_s() const override;
  const mjModel_* model() const override { return model_; }
  const mjData_* data() const override { return data_; }

 private:
  // mj_step1, or only its checks when reuse_forward and read()'s mj_forward left its stages
  void begin_step(bool reuse_forward);
  void apply_motor_drivers();
  // after each physics step: coil temperatures, the battery's charge, what the drivers report
  void update_power_and_heat(double dt_s);
  // the newest posted push request and force pulse, unless the poster holds the mailbox (then
  // they are taken at the next advance)
  void take_disturbance_requests();
  // the push's and the pulse's force on the state of this physics step (after mj_step1)
  void apply_disturbances();

  MujocoBackendConfig config_;
  TerrainGeometry terrain_;
  // the constructor's lookups and start pose (throws on a model without them)
  void find_model_elements();

  mjModel_* model_ = nullptr;
  mjData_* data_ = nullptr;
  JointCommand command_{};
  // a late actuation (config.model_error.actuation_delay_s): the commands written and not yet
  // reached the drivers, oldest first, each with the robot time it reaches them
  struct PendingCommand {
    double reaches_drivers_s = 0.0;
    JointCommand command{};
  };
  std::array<PendingCommand, 32> pending_{};
  std::size_t pending_first_ = 0;
  std::size_t pending_count_ = 0;
  double actuation_delay_s_ = 0.0;  // whole physics steps
  // the commands whose time has come reach the drivers (command_)
  void deliver_pending_commands();
  void deliver_oldest_pending_command();
  // the model error's mass, centre of mass, friction and motor strength (constructor)
  void apply_model_error();
  // the configured keyframe at the configured height (constructor, after the model error)
  void reset_to_start_pose();
  JointArray<int> qpos_address_{};
  JointArray<int> dof_address_{};
  JointArray<int> actuator_id_{};
  int trunk_body_ = -1;
  std::array<int, kNumLegs> foot_geom_{};
  std::array<double, kNumLegs> foot_friction_{};  // the model's sliding friction of each foot
  std::array<int, kNumLegs> foot_priority_{};
  int imu_quat_address_ = -1;
  int imu_gyro_address_ = -1;
  int imu_accel_address_ = -1;
  JointArray<double> applied_torque_{};
  JointArray<MotorDriverMode> driver_mode_ = all_motor_mode();  // of the last physics step
  bool sensors_stale_ = false;
  // read()'s mj_forward computed the position and velocity stages of the present state, and
  // nothing has changed the state or the model since: the next physics step need not repeat them
  bool forward_is_current_ = false;
  std::vector<MotorThermalModel> thermal_;
  BatteryModel battery_;
  ThermalMass main_board_;
  JointArray<std::uint32_t> motor_faults_{};  // what each driver reports (and stops on)
  double bus_voltage_v_ = 0.0;                // the pack's voltage as the drivers see it (filtered)
  std::mt19937 rng_;
  std::normal_distribution<double> unit_normal_{0.0, 1.0};
  // push mailbox: written by any thread, read when the robot steps
  std::mutex push_mutex_;
  PushRequest posted_push_;
  ForcePulse posted_pulse_;
  std::uint64_t posted_pulses_ = 0;  // pulses posted so far: a new one is taken once
  // the stepping thread's push
  PushRequest push_;
  PushSpring push_spring_;
  bool pushing_ = false;  // the push's force is on the trunk
  ForcePulse pulse_;
  std::uint64_t taken_pulses_ = 0;
  double pulse_end_s_ = -1.0;  // simulated time the pulse ends
  bool pulsing_ = false;       // the pulse's force is on the trunk
};

}  // namespace cerebellum
