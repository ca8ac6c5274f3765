#include "cli/drive_command.hpp"

#include <cerebellum/highlevel_client.hpp>

#include <chrono>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <thread>

#include "cli/cmd_options.hpp"
#include "cli/drive_options.hpp"
#include "teleop/pad_mapping.hpp"
#include "cli/sdl_gamepad.hpp"
#include "cli/stop_signal.hpp"
#include "cli/virtual_pad.hpp"
#include "control/locomotion/gait_table.hpp"
#include "core/text_file.hpp"
#include "io/lcm_highlevel/highlevel_wire.hpp"

namespace cerebellum {
namespace {

using Clock = std::chrono::steady_clock;

// the pad is sampled, and the command repeated, at the rate the interface's examples use
constexpr auto kSamplePeriod = std::chrono::milliseconds(static_cast<int>(kClientHeartbeatPeriodS * 1000.0));
// how often SDL's events are taken: a button press is sent at once, not at the next sample
constexpr auto kPollPeriod = std::chrono::milliseconds(10);
// a virtual pad's script is a few lines
constexpr std::size_t kMaxScriptBytes = 1 << 16;

std::string mode_and_gait(int mode, int gait_id) {
  const ModeInfo* info = find_mode(mode);
  std::string text = "mode " + std::to_string(mode) + " (" + (info != nullptr ? info->name : "?") + ") gait " +
                     std::to_string(gait_id);
  if (mode == static_cast<int>(ModeId::Locomotion)) {
    if (const GaitSpec* gait = find_gait(gait_id)) text += std::string(" (") + gait->name + ")";
  }
  return text;
}

// the heartbeat at the sampling rate, not the client's default
HighLevelClientOptions client_options(int ttl) {
  HighLevelClientOptions options = highlevel_client_options(ttl);
  options.heartbeat_period = kSamplePeriod;
  return options;
}

bool send(HighLevelClient& client, const DriveStep& step) {
  if (!step.is_new) return true;
  if (client.send(encode_robot_control_cmd(step.command)) != HighLevelClientStatus::Ok) {
    std::fprintf(stderr, "drive: cannot send: %s\n", client.last_error().c_str());
    return false;
  }
  return true;
}

// what the robot is left with: the velocity zeroed, sent once, then no heartbeat (the MC damps 0.5 s later)
void send_stop(HighLevelClient& client, PadMapping& mapping, const char* why) {
  const DriveStep stop = mapping.stop();
  send(client, stop);
  std::printf("drive: %s: sent the stop (%s, zero velocity); no heartbeat from now on\n", why,
              mode_and_gait(stop.command.mode, stop.command.gait_id).c_str());
  std::fflush(stdout);
  client.stop();
}

}  // namespace

int run_drive_command(const std::vector<std::string>& args) {
  DriveOptions options;
  try {
    options = parse_drive_options(args);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "cerebellum %s\n", e.what());
    return 2;
  }
  if (options.help) {
    std::fputs(drive_usage().c_str(), stdout);
    return 0;
  }
  std::vector<VirtualPadEvent> script;
  if (options.virtual_pad_script) {
    try {
      std::string error;
      const std::optional<std::string> text = read_text_file(*options.virtual_pad_script, kMaxScriptBytes, error);
      if (!text) throw std::invalid_argument(error);
      script = parse_virtual_pad_script(*text);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "drive: %s: %s\n", options.virtual_pad_script->c_str(), e.what());
      return 2;
    }
  }

  StopSignal stop_signal;  // before SDL's and the client's threads, so they inherit the blocked signals
  std::optional<SdlGamepad> pad;
  std::optional<VirtualPad> virtual_pad;  // after the pad: unplugged before SDL stops
  try {
    pad.emplace();
    if (options.virtual_pad_script) virtual_pad.emplace(std::move(script));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "drive: %s\n", e.what());
    return 1;
  }
  HighLevelClient client(client_options(options.ttl));
  if (const HighLevelClientStatus status = client.start(); status != HighLevelClientStatus::Ok) {
    std::fprintf(stderr, "drive: %s: %s\n", to_string(status), client.last_error().c_str());
    return 1;
  }
  std::fputs(pad_mapping_help().c_str(), stdout);
  std::puts("drive: waiting for a gamepad (plug one in; Ctrl-C ends)");
  std::fflush(stdout);

  PadMapping mapping;
  int sent_mode = -1;
  std::optional<robot_control_response_lcmt> shown;
  Clock::time_point next_sample = Clock::now();
  while (true) {
    if (stop_signal.flag().load()) {
      send_stop(client, mapping, "interrupted");
      return 0;
    }
    if (virtual_pad) virtual_pad->play();
    bool pressed = false;
    for (PadEvent event = pad->poll(); event != PadEvent::None; event = pad->poll()) {
      if (event == PadEvent::Plugged) {
        std::printf("drive: %s plugged in\n", pad->name().c_str());
        std::fflush(stdout);
        next_sample = Clock::now();
      }
      if (event == PadEvent::Unplugged) {
        send_stop(client, mapping, "gamepad unplugged");
        return 0;
      }
      pressed = pressed || event == PadEvent::Pressed;
    }
    if (pad->connected() && (pressed || Clock::now() >= next_sample)) {
      const DriveStep step = mapping.next(pad->sample());
      if (!send(client, step)) return 1;
      if (step.is_new && (pressed || step.command.mode != sent_mode)) {
        std::printf("drive: sent %s\n", mode_and_gait(step.command.mode, step.command.gait_id).c_str());
        std::fflush(stdout);
      }
      if (step.is_new) sent_mode = step.command.mode;
      next_sample = Clock::now() + kSamplePeriod;
    }
    const std::optional<robot_control_response_lcmt> now = client.latest_response();
    if (now && (!shown || now->mode != shown->mode || now->gait_id != shown->gait_id ||
                now->switch_status != shown->switch_status)) {
      std::printf("drive: robot %s switch_status %d\n", mode_and_gait(now->mode, now->gait_id).c_str(),
                  now->switch_status);
      std::fflush(stdout);
      shown = now;
    }
    std::this_thread::sleep_for(kPollPeriod);
  }
}

}  // namespace cerebellum
