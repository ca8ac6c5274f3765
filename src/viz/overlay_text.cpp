#include "viz/overlay_text.hpp"

#include <cstdio>

namespace cerebellum {
namespace {

std::string format(const char* pattern, double a, double b, double c) {
  char text[96];
  std::snprintf(text, sizeof text, pattern, a, b, c);
  return text;
}

}  // namespace

std::string mode_name(int mode) {
  if (const ModeInfo* info = find_mode(mode)) return info->name;
  return "mode " + std::to_string(mode);
}

const char* switch_status_name(SwitchStatus status) {
  switch (status) {
    case SwitchStatus::Done: return "done";
    case SwitchStatus::Transitioning: return "transitioning";
    case SwitchStatus::EmergencyStop: return "emergency stop";
    case SwitchStatus::HighDamping: return "high damping";
    case SwitchStatus::Lifted: return "lifted";
    case SwitchStatus::BanTransition: return "ban transition";
    case SwitchStatus::OverHeat: return "over heat";
    case SwitchStatus::LowBattery: return "low battery";
  }
  return "unknown";
}

OverlayText status_overlay(const SimSnapshot& snapshot, const std::string& run_state, const std::string& keys_state) {
  const auto& est = snapshot.estimated_velocity_body;
  const auto& truth = snapshot.true_velocity_body;
  const auto& cmd = snapshot.commanded_velocity;
  // four short rows: small enough for a corner of the picture, away from the followed robot
  OverlayText text;
  text.titles = format("%.2f s", snapshot.time_s, 0, 0) + "\ncommanded\nestimated\ntruth";
  text.values = "mode " + std::to_string(snapshot.status.mode) + " " + mode_name(snapshot.status.mode) + ", gait " +
                std::to_string(snapshot.status.gait_id) + ", " + switch_status_name(snapshot.status.switch_status) +
                "\n" + format("vx %+.2f  vy %+.2f m/s  wz %+.2f rad/s", cmd[0], cmd[1], cmd[2]) + "\n" +
                format("vx %+.2f  vy %+.2f m/s  wz %+.2f rad/s", est[0], est[1], est[2]) +
                format("  height %.3f m", snapshot.estimated_height_m, 0, 0) + "\n" +
                format("vx %+.2f  vy %+.2f m/s  wz %+.2f rad/s", truth[0], truth[1], truth[2]) +
                format("  height %.3f m", snapshot.true_height_m, 0, 0);
  // the robot's health
  text.titles += "\nrobot";
  text.values += "\n";
  if (snapshot.battery_soc_percent >= 0.0) {
    text.values += format("battery %.1f %%  %.1f V  ", snapshot.battery_soc_percent, snapshot.battery_v, 0);
  }
  const auto leg = static_cast<std::size_t>(snapshot.hottest_motor) / kJointsPerLeg;
  const auto joint = static_cast<std::size_t>(snapshot.hottest_motor) % kJointsPerLeg;
  text.values += format("hottest motor %.0f C ", snapshot.hottest_motor_c, 0, 0) + "(" + kLegNames[leg % kNumLegs] +
                 " " + kJointNames[joint] + ")";
  if (snapshot.faulty_motors != 0) {
    text.values += "  faulty motors:";
    for (std::size_t i = 0; i < kNumJoints; ++i) {
      if (snapshot.faulty_motors & (1u << i)) {
        text.values += ' ';
        text.values += std::to_string(i);
      }
    }
  }
  if (!run_state.empty()) {
    text.titles += "\nrun";
    text.values += "\n" + run_state;
  }
  if (!keys_state.empty()) {
    text.titles += "\nkeys";
    text.values += "\n" + keys_state;
  }
  return text;
}

}  // namespace cerebellum
