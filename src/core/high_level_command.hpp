// The high-level interface's command and status, as the MC sees them (mirrors robot_control_cmd
// and robot_control_response of the CyberDog2 LCM interface, without the transport).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "core/joint_layout.hpp"
#include "core/types.hpp"

namespace cerebellum {

// mode ids of the CyberDog2 high-level interface
enum class ModeId : int {
  Off = 0,
  QpStand = 3,
  PureDamper = 7,
  Lifted = 9,
  Locomotion = 11,
  RecoveryStand = 12,
  LowLevelMotor = 15,
  Jump3d = 16,
  PoseControl = 21,
  ForceJump = 22,
  Motion = 62,
  TwoLegStand = 64,
};

// every mode of the interface, once: the transition table, is_known_mode and names read this
struct ModeInfo {
  ModeId id;
  const char* name;
};
inline constexpr std::array<ModeInfo, 12> kAllModes{{
    {ModeId::Off, "off"},
    {ModeId::QpStand, "qp stand"},
    {ModeId::PureDamper, "pure damper"},
    {ModeId::Lifted, "lifted"},
    {ModeId::Locomotion, "locomotion"},
    {ModeId::RecoveryStand, "recovery stand"},
    {ModeId::LowLevelMotor, "low-level motor"},
    {ModeId::Jump3d, "jump 3d"},
    {ModeId::PoseControl, "pose control"},
    {ModeId::ForceJump, "force jump"},
    {ModeId::Motion, "motion"},
    {ModeId::TwoLegStand, "two-leg stand"},
}};

// the entry of a mode id, or nullptr for a number the interface does not define
constexpr const ModeInfo* find_mode(int mode) {
  for (const ModeInfo& info : kAllModes) {
    if (static_cast<int>(info.id) == mode) return &info;
  }
  return nullptr;
}

// the largest mode id: tables indexed by mode id have kMaxModeId + 1 entries
constexpr int max_mode_id() {
  int largest = 0;
  for (const ModeInfo& info : kAllModes) largest = std::max(largest, static_cast<int>(info.id));
  return largest;
}
inline constexpr int kMaxModeId = max_mode_id();

enum class SwitchStatus : int {
  Done = 0,
  Transitioning = 1,
  EmergencyStop = 2,
  HighDamping = 3,
  Lifted = 4,
  BanTransition = 5,
  OverHeat = 6,
  LowBattery = 7,
};

struct HighLevelCommand {
  int mode = 0;
  int gait_id = 0;
  int contact = 0;
  int life_count = 0;
  std::array<float, 3> vel_des{};
  std::array<float, 3> rpy_des{};
  std::array<float, 3> pos_des{};
  std::array<float, 6> acc_des{};
  std::array<float, 3> ctrl_point{};
  std::array<float, 6> foot_pose{};
  std::array<float, 2> step_height{};
  std::int32_t value = 0;
  std::int32_t duration = 0;  // ms
};

// the high-level clients: one holds the robot at a time (HighLevelMachine's lease)
// (the viewer's keyboard: a person driving from `cerebellum sim --viewer`, in the MC's own process)
enum class HighLevelSource : std::uint8_t { CyberDog2Lcm = 0, AlienGoUdp = 1, ViewerKeyboard = 2 };
inline constexpr std::size_t kHighLevelSourceCount = 3;
constexpr const char* source_name(HighLevelSource source) {
  switch (source) {
    case HighLevelSource::CyberDog2Lcm: return "the CyberDog2 LCM client (robot_control_cmd)";
    case HighLevelSource::AlienGoUdp: return "the AlienGo UDP client (HighCmd)";
    case HighLevelSource::ViewerKeyboard: return "the viewer's keyboard";
  }
  return "an unknown client";
}

// the most commands of one client the machine takes in one tick: whatever arrives, a tick's input
// work is bounded (a client sending faster fills only its own ring, where the rest is dropped)
inline constexpr std::size_t kCommandsPerSourcePerTick = 8;

// how often a client repeats its command as the heartbeat: the rate the seeds' examples send at
// (10 Hz), well inside the machine's 0.5 s timeout
inline constexpr double kClientHeartbeatPeriodS = 0.1;

// a command with the robot time it arrived at and the client it came from
struct TimedCommand {
  HighLevelCommand command;
  double received_s = 0.0;
  HighLevelSource source = HighLevelSource::CyberDog2Lcm;
};

struct HighLevelStatus {
  int mode = 0;
  int gait_id = 0;
  int contact = 0;            // bit i: leg i's foot force > 5 N
  int order_process_bar = 0;  // percent
  SwitchStatus switch_status = SwitchStatus::Done;
  int ori_error = 0;
  int footpos_error = 0;                                       // bit 3 * leg + axis
  JointArray<std::uint32_t> motor_faults{};                    // MotorFault bits per motor, as the drivers report them
  JointArray<MotorDriverMode> driver_mode = all_motor_mode();  // each driver's mode (bits 30..31)
};

// a frame in the odometry's world frame: its origin (x, y, z) and heading (yaw about z), as the
// AlienGo sport mode fixes it at the instant it starts (seed 004 section 2.3: origin at the body's
// centre, x forward, y left, z up)
struct SportFrame {
  std::array<double, 3> origin{};
  double yaw_rad = 0.0;
};

// what the high-level state machine reports after each tick, in the cycle record (observers read
// it there, never the machine): the response fields, the command its running mode was entered or
// last updated with, and the client holding the robot (none before the first command)
struct HighLevelReport {
  HighLevelStatus status;
  HighLevelCommand running_command;
  std::optional<HighLevelSource> holder;
  // the AlienGo client's sport mode as HighState reports it: its session's mode once the MC runs
  // what that mode was translated into
  int aliengo_mode = 0;
  // the AlienGo client's sport frame, set when its session started: HighState.position and mode
  // 3's targets are in it (before the first session: the odometry's own frame)
  SportFrame aliengo_frame;
};

}  // namespace cerebellum
