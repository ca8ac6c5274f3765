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

OverlayText status_overlay(const SimSnapshot& snapshot, const std::string& run_state) {
  const auto& est = snapshot.estimated_velocity_body;
  const auto& truth = snapshot.true_velocity_body;
  const auto& cmd = snapshot.commanded_velocity;
  OverlayText text;
  text.titles = "time\nmode\ngait\nswitch\nvx vy wz commanded\nvx vy wz estimated\nvx vy wz truth\nheight est / truth";
  text.values = format("%.2f s", snapshot.time_s, 0, 0) + "\n" + std::to_string(snapshot.status.mode) + " " +
                mode_name(snapshot.status.mode) + "\n" + std::to_string(snapshot.status.gait_id) + "\n" +
                switch_status_name(snapshot.status.switch_status) + "\n" +
                format("%+.2f %+.2f m/s %+.2f rad/s", cmd[0], cmd[1], cmd[2]) + "\n" +
                format("%+.2f %+.2f m/s %+.2f rad/s", est[0], est[1], est[2]) + "\n" +
                format("%+.2f %+.2f m/s %+.2f rad/s", truth[0], truth[1], truth[2]) + "\n" +
                format("%.3f / %.3f m", snapshot.estimated_height_m, snapshot.true_height_m, 0);
  if (!run_state.empty()) {
    text.titles += "\nrun";
    text.values += "\n" + run_state;
  }
  return text;
}

}  // namespace cerebellum
