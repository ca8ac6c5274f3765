#include "modes/aliengo_session.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "control/locomotion/gait_table.hpp"
#include "control/stance_frame.hpp"
#include "modes/command_ranges.hpp"

namespace cerebellum {
namespace {

using M = AlienGoMode;

// the vendor's legal moves (docs/aliengo-udp.md): the moves its walk example makes and those of the
// seed's documented sequences (sit down 2 -> 1 -> 6 -> 5 -> 7, stand up 7 -> 5 -> 6, unlock walking
// 6 -> 1 -> 2, its table's "previous mode" of 6: mode 1); staying in a mode is always legal and any
// mode may go to damping
bool legal_move(M from, M to) {
  if (from == to || to == M::Damping) return true;
  switch (from) {
    case M::Idle: return to == M::ForceStand || to == M::WalkVelocity || to == M::WalkPosition;
    case M::ForceStand:
      return to == M::Idle || to == M::WalkVelocity || to == M::WalkPosition || to == M::StandDown || to == M::StandUp;
    case M::WalkVelocity: return to == M::Idle || to == M::ForceStand;  // 1: only to stop the stair gait
    case M::WalkPosition: return to == M::Idle;
    case M::StandDown: return to == M::StandUp;
    case M::StandUp: return to == M::StandDown || to == M::ForceStand;
    case M::Damping: return to == M::StandDown || to == M::Recovery;
    case M::Recovery: return to == M::ForceStand || to == M::Idle || to == M::StandDown;
    case M::WalkPath: return false;
  }
  return false;
}

// the MC's gait for HighCmd.gaitType: trot (the variable-frequency trot), running trot (the
// flying trot), stairs (the slow trot, high feet); the stand of the gait table
constexpr int kTrotGait = kVariableTrotGaitId;
constexpr int kRunningTrotGait = kFlyingTrotGaitId;
constexpr int kStairsGait = kSlowTrotGaitId;
constexpr int kStandGait = kStandGaitId;

HighLevelCommand mc_command(ModeId mode, int gait = 0) {
  HighLevelCommand c;
  c.mode = static_cast<int>(mode);
  c.gait_id = gait;
  return c;
}

bool same_request(const HighLevelCommand& a, const HighLevelCommand& b) {
  return a.mode == b.mode && a.gait_id == b.gait_id && a.vel_des == b.vel_des && a.rpy_des == b.rpy_des &&
         a.pos_des == b.pos_des && a.step_height == b.step_height;
}

// the MC's modes in which the robot is up on its feet
bool robot_up(int mc_mode, int mc_progress) {
  const auto mode = static_cast<ModeId>(mc_mode);
  if (mode == ModeId::RecoveryStand) return mc_progress >= 100;
  return mode == ModeId::Locomotion || mode == ModeId::QpStand || mode == ModeId::PoseControl;
}

}  // namespace

AlienGoSession::AlienGoSession(const AlienGoSessionConfig& config)
    : config_(config), walk_to_position_(config.walk_to_position) {}

void AlienGoSession::start(const RobotState& state) {
  active_ = true;
  mode_ = M::Idle;
  stairs_walking_ = false;
  silenced_ = false;
  origin_.position = state.position_world.head<2>();
  origin_.yaw_rad = state.rpy.z();
  frame_.origin = {state.position_world.x(), state.position_world.y(), state.position_world.z()};
  frame_.yaw_rad = origin_.yaw_rad;
}

HighLevelCommand AlienGoSession::stand_command() const {
  HighLevelCommand c = mc_command(ModeId::Locomotion, kStandGait);
  c.pos_des[2] = last_submitted_.mode == static_cast<int>(ModeId::Locomotion) ? last_submitted_.pos_des[2] : 0.0f;
  return c;
}

HighLevelCommand AlienGoSession::translate(const AlienGoCommand& command, const RobotState& state, int mc_mode,
                                           int mc_progress) {
  const float height = static_cast<float>(kDefaultBodyHeightM + command.body_height_m);
  switch (mode_) {
    case M::Idle: {
      // sport mode starts standing; a trot stops by itself, the stair gait does not
      if (!robot_up(mc_mode, mc_progress)) return mc_command(ModeId::RecoveryStand);
      if (stairs_walking_) {
        HighLevelCommand c = mc_command(ModeId::Locomotion, kStairsGait);
        c.step_height = {static_cast<float>(config_.stairs_step_height_m),
                         static_cast<float>(config_.stairs_step_height_m)};
        return c;
      }
      return mc_command(ModeId::Locomotion, kStandGait);
    }
    case M::ForceStand: {
      stairs_walking_ = false;
      HighLevelCommand c = mc_command(ModeId::QpStand);
      // HighCmd's euler angles are right-handed (+pitch lowers the head, as HighState.imu.rpy
      // reads it); robot_control_cmd's pitch raises it (commanded_pose.hpp)
      c.rpy_des = {command.rpy[0], -command.rpy[1], command.rpy[2]};
      c.pos_des[2] = height;
      return c;
    }
    case M::WalkVelocity: {
      const bool stairs = command.gait_type == static_cast<int>(AlienGoGait::Stairs);
      stairs_walking_ = stairs;
      const int gait = stairs                                                            ? kStairsGait
                       : command.gait_type == static_cast<int>(AlienGoGait::TrotRunning) ? kRunningTrotGait
                                                                                         : kTrotGait;
      HighLevelCommand c = mc_command(ModeId::Locomotion, gait);
      float vx = command.velocity[0];
      if (stairs) {
        vx = std::clamp(vx, static_cast<float>(config_.stairs_min_vx_m_s),
                        static_cast<float>(config_.stairs_max_vx_m_s));
      }
      c.vel_des = {vx, command.velocity[1], command.yaw_speed};
      const double base = stairs ? config_.stairs_step_height_m : config_.trot_step_height_m;
      const auto step = static_cast<float>(kStepHeightRange.clamp(base + command.foot_raise_m));
      c.step_height = {step, step};
      c.pos_des[2] = height;
      return c;
    }
    case M::WalkPosition: {
      stairs_walking_ = false;
      // the target in the world: the sport frame fixed at start, turned by its yaw
      const double c0 = std::cos(origin_.yaw_rad), s0 = std::sin(origin_.yaw_rad);
      target_world_.position = origin_.position + Eigen::Vector2d(c0 * command.position[0] - s0 * command.position[1],
                                                                  s0 * command.position[0] + c0 * command.position[1]);
      target_world_.yaw_rad = wrap_angle(origin_.yaw_rad + command.rpy[2]);
      Pose2d trunk;
      trunk.position = state.position_world.head<2>();
      trunk.yaw_rad = state.rpy.z();
      const int level = std::clamp(command.speed_level, 0, 2);
      const WalkToPositionOutput out =
          walk_to_position_.update(trunk, target_world_, config_.speed_level_m_s[static_cast<std::size_t>(level)]);
      HighLevelCommand c = mc_command(ModeId::Locomotion, out.arrived ? kStandGait : kTrotGait);
      c.vel_des = {static_cast<float>(out.velocity.x()), static_cast<float>(out.velocity.y()),
                   static_cast<float>(out.velocity.z())};
      const auto step = static_cast<float>(config_.trot_step_height_m);
      c.step_height = {step, step};
      c.pos_des[2] = height;
      return c;
    }
    case M::StandDown: stairs_walking_ = false; return mc_command(ModeId::PureDamper, 1);
    case M::StandUp:
    case M::Recovery: stairs_walking_ = false; return mc_command(ModeId::RecoveryStand);
    case M::Damping: stairs_walking_ = false; return mc_command(ModeId::PureDamper, 0);
    case M::WalkPath: break;
  }
  return last_submitted_;
}

AlienGoStep AlienGoSession::emit(const HighLevelCommand& command) {
  HighLevelCommand c = command;
  // a new request gets a new life_count; the same one is a heartbeat
  if (life_count_ == 0 || !same_request(c, last_submitted_)) ++life_count_;
  c.life_count = life_count_;
  last_submitted_ = c;
  AlienGoStep step;
  step.submit = c;
  return step;
}

AlienGoStep AlienGoSession::on_command(const AlienGoCommand& command, const RobotState& state, int mc_mode,
                                       int mc_progress, double now_s) {
  if (!active_) start(state);
  last_command_s_ = now_s;
  silenced_ = false;
  const char* refusal = nullptr;
  if (command.mode < 0 || command.mode >= kAlienGoModeCount) {
    refusal = "unknown mode (0..8)";
  } else if (command.mode == static_cast<int>(M::WalkPath)) {
    refusal = "mode 4 (path walking) is not supported";
  } else if (!legal_move(mode_, static_cast<M>(command.mode))) {
    refusal = "illegal move from the current mode: staying";
  } else {
    const auto next = static_cast<M>(command.mode);
    if (next == M::WalkPosition && mode_ != M::WalkPosition) walk_to_position_.reset();
    mode_ = next;
  }
  // a refused mode keeps the current one with the command's values where they apply
  AlienGoStep step = emit(translate(command, state, mc_mode, mc_progress));
  step.refusal = refusal;
  return step;
}

AlienGoStep AlienGoSession::on_silence(const RobotState&, int, int, double now_s) {
  if (!active_) return {};
  const double silent_s = now_s - last_command_s_;
  if (silent_s < config_.silence_stand_s) return {};
  if (silent_s > config_.stand_hold_s + config_.lie_down_s) {
    // no more heartbeats: the MC's heartbeat timeout damps the robot; the next HighCmd starts a
    // new session (a new sport frame)
    active_ = false;
    return {};
  }
  if (!silenced_) {
    silenced_ = true;
    stairs_walking_ = false;
  }
  // down or being damped already: keep it so
  const auto submitted = static_cast<ModeId>(last_submitted_.mode);
  if (submitted == ModeId::PureDamper) return emit(last_submitted_);
  // held long enough: lie down in position control, then the timeout damps a lying robot
  if (silent_s > config_.stand_hold_s) return emit(mc_command(ModeId::PureDamper, 1));
  if (submitted == ModeId::RecoveryStand || submitted == ModeId::QpStand) return emit(last_submitted_);
  return emit(stand_command());
}

}  // namespace cerebellum
