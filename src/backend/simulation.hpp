// What only tools and tests may see and do of a simulated robot, beside the RobotBackend the MC
// runs on: simulator truth, placing the body, disturbances, and the model and state to render.
// Never handed to the controller; a hardware robot has none.
#pragma once

#include <array>

#include "backend/push_request.hpp"
#include "core/types.hpp"

// MuJoCo's model and data, named without including MuJoCo
struct mjModel_;
struct mjData_;

namespace cerebellum {

// simulator truth, for tests and tools only: never handed to the controller
struct GroundTruth {
  std::array<double, 3> position{};        // world
  std::array<double, 4> quat{1, 0, 0, 0};  // w, x, y, z, body to world
  std::array<double, 3> velocity_world{};
  std::array<double, 3> angular_velocity_body{};
  // each foot (FR, FL, RR, RL) touches the ground or terrain in the simulator's contact list
  std::array<bool, kNumLegs> foot_contact{};
  // the ground's vertical force on each foot (N, world z), from the simulator's contact forces
  std::array<double, kNumLegs> foot_force_z_n{};
  // joints in the SDK / URDF convention (core/joint_layout.hpp); tau is what the motors applied
  JointArray<double> q{};
  JointArray<double> qd{};
  JointArray<double> tau{};
  // the ground's top surface under the trunk's origin (the terrain's, 0 on flat ground)
  double ground_height_m = 0.0;
};

class Simulation {
 public:
  virtual ~Simulation() = default;

  virtual double time_s() const = 0;
  virtual double physics_timestep_s() const = 0;
  virtual GroundTruth ground_truth() const = 0;

  // place the trunk (tests and tools): position in world, orientation w, x, y, z; zero velocity
  virtual void set_base_pose(const std::array<double, 3>& position, const std::array<double, 4>& quat) = 0;
  virtual void set_joint_positions(const JointArray<double>& q) = 0;
  // a force on the trunk COM (world frame) that stays until changed, for push tests; same
  // thread as the robot's steps
  virtual void set_external_force(const std::array<double, 3>& force_n) = 0;
  // any thread: the newest push request (the viewer's drag); the simulation turns it into a force
  // on the trunk at its own physics steps, and lifts the force once the request is inactive
  virtual void request_push(const PushRequest& request) = 0;
  // any thread: a force pulse on the trunk COM from the simulation's next step on, for
  // pulse.duration_s of simulated time, added to the push; replaces a pulse still running
  virtual void request_force_pulse(const ForcePulse& pulse) = 0;
  // the sliding friction between one foot (FR, FL, RR, RL) and whatever it touches, in place of
  // the contact's own; reset restores the model's. Same thread as the robot's steps
  virtual void set_foot_friction(std::size_t leg, double friction) = 0;
  virtual void reset_foot_friction(std::size_t leg) = 0;

  // for rendering and inspection: read only, in the thread that steps the robot (or while it
  // does not step)
  virtual const mjModel_* model() const = 0;
  virtual const mjData_* data() const = 0;
};

}  // namespace cerebellum
