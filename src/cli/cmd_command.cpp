#include "cli/cmd_command.hpp"

#include <cerebellum/highlevel_client.hpp>

#include <array>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <thread>

#include "cli/cmd_options.hpp"
#include "cli/diagnostics_listener.hpp"
#include "cli/stop_signal.hpp"
#include "io/common/motor_error_word.hpp"

namespace cerebellum {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

constexpr milliseconds kSlice{50};

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

milliseconds to_ms(double seconds) { return milliseconds(static_cast<long long>(seconds * 1000.0)); }

const char* switch_status_name(int status) {
  static constexpr std::array<const char*, 8> kNames{"Done",   "TRANSITIONING", "ESTOP",     "EDAMP",
                                                     "LIFTED", "BAN_TRANS",     "OVER_HEAT", "LOW_BAT"};
  return status >= 0 && status < static_cast<int>(kNames.size()) ? kNames[static_cast<std::size_t>(status)] : "?";
}

std::string describe(const robot_control_response_lcmt& r) {
  char text[160];
  std::snprintf(text, sizeof text,
                "mode %d gait %d bar %d switch %d (%s) contact 0x%x ori_error %d footpos_error 0x%03x", r.mode,
                r.gait_id, r.order_process_bar, r.switch_status, switch_status_name(r.switch_status),
                static_cast<unsigned>(r.contact) & 0xFFu, r.ori_error, static_cast<unsigned>(r.footpos_error) & 0xFFFu);
  std::string out = text;
  std::string motors;
  for (int i = 0; i < 12; ++i) {
    const auto word = static_cast<std::uint32_t>(r.motor_error[i]);
    if (word == kMotorErrorWordHealthy) continue;
    char motor[32];
    std::snprintf(motor, sizeof motor, " %d:0x%08x", i, word);
    motors += motor;
    if (const std::string names = motor_fault_names(motor_faults_from_word(word)); !names.empty()) {
      motors += " (";
      motors += names;
      motors += ')';
    }
  }
  return out + (motors.empty() ? " motors ok" : " motor_error" + motors);
}

std::string describe(const localization_lcmt& o) {
  char text[200];
  std::snprintf(text, sizeof text,
                "t %.3f s xyz %+.3f %+.3f %+.3f m rpy %+.3f %+.3f %+.3f rad vBody %+.2f %+.2f %+.2f m/s",
                static_cast<double>(o.timestamp) * 1e-9, o.xyz[0], o.xyz[1], o.xyz[2], o.rpy[0], o.rpy[1], o.rpy[2],
                o.vBody[0], o.vBody[1], o.vBody[2]);
  return text;
}

std::string no_response_hint(const HighLevelClientOptions& options) {
  return "no robot_control_response on " + options.response_url +
         " (is `cerebellum sim` running with highlevel.enabled: true, in this network namespace?)";
}

// waits for the mode in slices, so Ctrl-C is noticed; Timeout when interrupted too
HighLevelClientStatus wait_for_mode(HighLevelClient& client, const robot_control_cmd_lcmt& command, double timeout_s,
                                    const std::atomic<bool>& stop) {
  const Clock::time_point deadline = Clock::now() + to_ms(timeout_s);
  while (!stop.load()) {
    const HighLevelClientStatus status = client.wait_for_mode(command.mode, command.gait_id, kSlice);
    if (status != HighLevelClientStatus::Timeout || Clock::now() >= deadline) return status;
  }
  return HighLevelClientStatus::Timeout;
}

// keeps the heartbeat, reporting when the MC's mode, gait or switch status changes
void hold(HighLevelClient& client, const std::string& name, std::optional<double> hold_s,
          const std::atomic<bool>& stop) {
  if (hold_s) {
    std::printf("%s: holding for %.1f s (heartbeat every 50 ms)\n", name.c_str(), *hold_s);
  } else {
    std::printf("%s: holding until Ctrl-C (heartbeat every 50 ms)\n", name.c_str());
  }
  std::fflush(stdout);
  const Clock::time_point start = Clock::now();
  std::optional<robot_control_response_lcmt> shown = client.latest_response();
  while (!stop.load() && (!hold_s || seconds_since(start) < *hold_s)) {
    std::this_thread::sleep_for(kSlice);
    const std::optional<robot_control_response_lcmt> now = client.latest_response();
    if (now && shown &&
        (now->mode != shown->mode || now->gait_id != shown->gait_id || now->switch_status != shown->switch_status)) {
      std::printf("%s: now %s\n", name.c_str(), describe(*now).c_str());
      std::fflush(stdout);
    }
    if (now) shown = now;
  }
}

}  // namespace

int run_cmd_command(const std::vector<std::string>& args) {
  CmdOptions options;
  try {
    options = parse_cmd_options(args);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "cerebellum %s\n", e.what());
    return 2;
  }
  if (options.help) {
    std::fputs(cmd_usage().c_str(), stdout);
    return 0;
  }
  const std::string name = "cmd " + options.verb;
  const robot_control_cmd_lcmt& command = options.command;

  StopSignal stop_signal;  // before the client's threads, so they inherit the blocked signals
  const HighLevelClientOptions client_settings = highlevel_client_options(options.ttl);
  HighLevelClient client(client_settings);
  if (const HighLevelClientStatus status = client.start(); status != HighLevelClientStatus::Ok) {
    std::fprintf(stderr, "%s: %s: %s\n", name.c_str(), to_string(status), client.last_error().c_str());
    return 1;
  }
  const Clock::time_point start = Clock::now();
  if (const HighLevelClientStatus status = client.send(command); status != HighLevelClientStatus::Ok) {
    std::fprintf(stderr, "%s: %s: %s\n", name.c_str(), to_string(status), client.last_error().c_str());
    return 1;
  }
  std::printf("%s: sent mode %d gait %d duration %d ms (life_count %d)\n", name.c_str(), command.mode, command.gait_id,
              command.duration, client.life_count());
  std::fflush(stdout);

  const HighLevelClientStatus status = wait_for_mode(client, command, options.timeout_s, stop_signal.flag());
  const std::optional<robot_control_response_lcmt> response = client.latest_response();
  if (stop_signal.flag().load()) {
    std::printf("%s: interrupted; the MC goes to PureDamper 0.5 s after the last heartbeat\n", name.c_str());
    return 130;
  }
  if (status == HighLevelClientStatus::Refused) {
    std::fprintf(stderr, "%s: refused by the MC (switch_status 5 BAN_TRANS): %s; the MC's log names the reason\n",
                 name.c_str(), describe(*response).c_str());
    return 1;
  }
  if (status != HighLevelClientStatus::Ok) {
    const std::string why = response ? "the MC reports " + describe(*response) : no_response_hint(client_settings);
    std::fprintf(stderr, "%s: mode %d gait %d not reached within %.1f s: %s\n", name.c_str(), command.mode,
                 command.gait_id, options.timeout_s, why.c_str());
    return 1;
  }
  std::printf("%s: mode %d gait %d reached (order_process_bar %d) in %.2f s\n", name.c_str(), command.mode,
              command.gait_id, response->order_process_bar, seconds_since(start));
  std::fflush(stdout);
  if (!options.hold_s || *options.hold_s > 0.0) {
    hold(client, name, options.hold_s, stop_signal.flag());
    std::printf("%s: released; the MC goes to PureDamper 0.5 s after the last heartbeat\n", name.c_str());
  }
  client.stop();
  return 0;
}

int run_status_command(const std::vector<std::string>& args) {
  StatusOptions options;
  try {
    options = parse_status_options(args);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "cerebellum %s\n", e.what());
    return 2;
  }
  if (options.help) {
    std::fputs(status_usage().c_str(), stdout);
    return 0;
  }
  StopSignal stop_signal;
  const HighLevelClientOptions client_settings = highlevel_client_options(options.ttl);
  HighLevelClient client(client_settings);
  if (const HighLevelClientStatus status = client.start(); status != HighLevelClientStatus::Ok) {
    std::fprintf(stderr, "status: %s: %s\n", to_string(status), client.last_error().c_str());
    return 1;
  }
  std::optional<DiagnosticsListener> diagnostics;
  try {
    if (options.diagnostics) diagnostics.emplace(client_settings.response_url);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "status: %s\n", e.what());
    return 1;
  }
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / options.rate_hz));
  Clock::time_point next_line = Clock::now();
  Clock::time_point last_news = Clock::now();
  std::uint64_t responses_seen = 0;
  long lines = 0;
  while (!stop_signal.flag().load() && (!options.count || lines < *options.count)) {
    std::this_thread::sleep_for(std::min(milliseconds(10), std::chrono::duration_cast<milliseconds>(period)));
    const std::uint64_t responses = client.responses_received();
    if (responses != responses_seen) {
      responses_seen = responses;
      last_news = Clock::now();
    } else if (seconds_since(last_news) > options.timeout_s) {
      std::fprintf(stderr, "status: %s within %.1f s\n", no_response_hint(client_settings).c_str(), options.timeout_s);
      return 1;
    }
    if (diagnostics) {
      if (const std::optional<mc_diagnostics_lcmt> figures = diagnostics->poll()) {
        std::printf("%s\n", describe_diagnostics(*figures).c_str());
        std::fflush(stdout);
      }
    }
    const Clock::time_point now = Clock::now();
    if (responses_seen == 0 || now < next_line) continue;
    next_line = next_line + period < now ? now + period : next_line + period;
    const std::optional<robot_control_response_lcmt> response = client.latest_response();
    const std::optional<localization_lcmt> odometry = client.latest_odometry();
    std::printf("%s | %s\n", describe(*response).c_str(), odometry ? describe(*odometry).c_str() : "no odometry yet");
    std::fflush(stdout);
    ++lines;
  }
  client.stop();
  return 0;
}

}  // namespace cerebellum
