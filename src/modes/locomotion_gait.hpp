// One gait of the locomotion mode (11), and the registry the mode looks gaits up in. A new gait
// (trot, bound, user gait) is a LocomotionGait registered under its gait_id.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "core/contact_plan.hpp"
#include "core/robot_state.hpp"
#include "core/types.hpp"
#include "modes/command_ranges.hpp"
#include "core/high_level_command.hpp"

namespace cerebellum {

// a mode-11 command with its fields clamped to the gait's ranges
struct LocomotionCommand {
  int gait_id = 1;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // vx, vy (m/s, body), yaw rate (rad/s)
  double pitch_rad = 0.0;
  double height_m = kDefaultBodyHeightM;
  std::array<double, 2> step_height_m{};  // front, rear
  // the velocity limits the command was clamped to (LocomotionLimits): the gait table's unless the
  // MC is configured beyond the product; none for gaits without (stands, user gaits)
  std::optional<VelocityLimits> velocity_limits;
  std::int32_t value = 0;
  std::int32_t duration_ms = 0;
  // set by gait 1 while its trot catches a push (LocomotionTarget::catching_push)
  bool catching_push = false;
  HighLevelCommand raw;  // every field as received, for gaits that give them their own meaning
};

class LocomotionGait {
 public:
  virtual ~LocomotionGait() = default;
  // nullptr when the gait can run this command, else why not (a static string)
  virtual const char* check(const HighLevelCommand&) const { return nullptr; }
  // the gait takes over the robot (from another mode or another gait)
  virtual void start(const RobotState& state, const LocomotionCommand& command) = 0;
  // a new command for the running gait: velocity, height, pitch change without restarting
  virtual void update(const LocomotionCommand& command) = 0;
  virtual void run(const RobotState& state, JointCommand& command) = 0;
  // the contacts the last run() planned for the next tick (for the estimator); none unless it steps
  virtual ContactPlan contact_plan() const { return std::nullopt; }
  // another gait or mode takes over the robot
  virtual void stop() {}
  // gaits that drive the same walking controller (the passive trot wraps the walking gaits) hand
  // the robot over to each other mid-stride: take_over() continues from the running controller's
  // state instead of start()'s reset, and the previous gait is not stopped
  virtual const void* walking_controller() const { return this; }
  virtual void take_over(const RobotState& state, const LocomotionCommand& command) { start(state, command); }
  // true while the gait has given up and damps the joints (its controller failed)
  virtual bool damping_protection() const { return false; }
  // order_process_bar while this gait runs
  virtual int progress_percent() const = 0;
};

class GaitRegistry {
 public:
  // gait ids are int8 on the wire: 0..127
  static constexpr int kMaxGaitId = 127;
  // one gait object may serve several ids (stand 1 and 31)
  void add(int gait_id, LocomotionGait& gait);
  LocomotionGait* find(int gait_id) const;

 private:
  std::array<LocomotionGait*, kMaxGaitId + 1> gaits_{};
};

}  // namespace cerebellum
