// One AlienGo client's sport session: the vendor's mode state machine (legal moves, "stay" on an
// illegal one), each HighCmd translated into the MC's own high-level command (the CyberDog2
// modes that do the same), the mode-3 position controller in the frame fixed when sport mode
// started, and the streaming timeout: a silent client's robot stands, then is damped.
#pragma once

#include <array>
#include <optional>

#include "control/walk_to_position.hpp"
#include "core/robot_state.hpp"
#include "modes/aliengo_command.hpp"
#include "core/high_level_command.hpp"

namespace cerebellum {

struct AlienGoSessionConfig {
  // silent this long while walking: stand (a stream stopped, not a command)
  double silence_stand_s = 0.25;
  // the stand is held until this long after the last command; then the robot lies down actively
  // (position control) for lie_down_s; then no more heartbeats: the MC's heartbeat timeout
  // (0.5 s) damps the lying robot and ends the session. (Damping a standing robot lets it fall.)
  double stand_hold_s = 2.0;
  double lie_down_s = 2.5;
  double trot_step_height_m = 0.04;    // swing height of gaitType 0 / 1 before dFootRaiseHeight
  double stairs_step_height_m = 0.06;  // gaitType 2: higher feet
  // gaitType 2: slower (the vendor's advice for stairs)
  double stairs_min_vx_m_s = -0.2;
  double stairs_max_vx_m_s = 0.37;
  std::array<double, 3> speed_level_m_s{0.3, 0.6, 0.9};  // mode 3, speedLevel 0 / 1 / 2
  WalkToPositionConfig walk_to_position;
};

// what the session hands to the state machine, if anything
struct AlienGoStep {
  std::optional<HighLevelCommand> submit;
  // an illegal move or a refused mode this time (a static string), else nullptr
  const char* refusal = nullptr;
};

class AlienGoSession {
 public:
  explicit AlienGoSession(const AlienGoSessionConfig& config = {});

  // one decoded HighCmd at robot time now_s; state: the newest estimate; mc_mode / mc_progress:
  // the MC's running mode and its progress (the response fields)
  AlienGoStep on_command(const AlienGoCommand& command, const RobotState& state, int mc_mode, int mc_progress,
                         double now_s);
  // no HighCmd since the last call: the silence protection
  AlienGoStep on_silence(const RobotState& state, int mc_mode, int mc_progress, double now_s);

  bool active() const { return active_; }
  // the AlienGo mode echoed in HighState
  int mode() const { return static_cast<int>(mode_); }
  // the sport frame fixed when the session started (HighState.position is reported in it)
  const SportFrame& frame() const { return frame_; }

 private:
  void start(const RobotState& state);
  HighLevelCommand translate(const AlienGoCommand& command, const RobotState& state, int mc_mode, int mc_progress);
  HighLevelCommand stand_command() const;
  AlienGoStep emit(const HighLevelCommand& command);

  AlienGoSessionConfig config_;
  bool active_ = false;
  AlienGoMode mode_ = AlienGoMode::Idle;
  bool stairs_walking_ = false;  // the last walk was the stair gait: mode 0 does not stop it
  Pose2d origin_;                // the sport frame in the world
  SportFrame frame_;             // the same, with the trunk's height at start (what HighState reports)
  Pose2d target_world_;
  WalkToPosition walk_to_position_;
  double last_command_s_ = 0.0;
  bool silenced_ = false;
  HighLevelCommand last_submitted_;
  int life_count_ = 0;
};

}  // namespace cerebellum
