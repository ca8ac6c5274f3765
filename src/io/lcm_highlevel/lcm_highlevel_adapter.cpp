#include "io/lcm_highlevel/lcm_highlevel_adapter.hpp"

#include <lcm/lcm-cpp.hpp>

#include "io/common/wall_clock.hpp"
#include "io/lcm_common/lcm_url.hpp"
#include "io/lcm_highlevel/highlevel_wire.hpp"

namespace cerebellum {
namespace {

constexpr const char* kCommandChannel = "robot_control_cmd";
constexpr const char* kResponseChannel = "robot_control_response";
constexpr const char* kTemperatureChannel = "motor_temperature";
constexpr const char* kOdometryChannel = "global_to_robot";
constexpr const char* kInterfaceName = "highlevel";
constexpr int kRefusalLinesPerSecond = 5;
constexpr int kGaitFileLinesPerSecond = 5;

}  // namespace

LcmHighLevelAdapter::LcmHighLevelAdapter(ClientPort port, UserGaitUpload& user_gaits, const HighLevelLcmConfig& config,
                                         double loop_period_s, std::FILE* log)
    : port_(port),
      user_gaits_(user_gaits),
      log_(log),
      keepalive_s_(config.response_keepalive_s),
      command_lcm_(open_lcm_url(config.command_url, kInterfaceName)),
      response_lcm_(open_lcm_url(config.response_url, kInterfaceName)),
      odometry_lcm_(open_lcm_url(config.odometry_url, kInterfaceName)),
      schedule_(loop_period_s),
      refusal_log_(log, kInterfaceName, "refusals (BAN_TRANS) and clamps", kRefusalLinesPerSecond),
      gait_file_log_(log, kInterfaceName, "user_gait_file results", kGaitFileLinesPerSecond),
      count_log_period_(wall_seconds()) {
  command_lcm_->subscribe(kCommandChannel, &LcmHighLevelAdapter::on_command, this);
  command_lcm_->subscribe(kUserGaitFileChannel, &LcmHighLevelAdapter::on_gait_file, this);
  std::fprintf(log_,
               "highlevel: robot_control_cmd and user_gait_file on %s; robot_control_response and "
               "motor_temperature on %s; global_to_robot on %s\n",
               config.command_url.c_str(), config.response_url.c_str(), config.odometry_url.c_str());
  std::fflush(log_);
  thread_.start([this] { step(); }, [this] { drain(); });
}

LcmHighLevelAdapter::~LcmHighLevelAdapter() { thread_.stop(); }

void LcmHighLevelAdapter::on_cycle(const CycleRecord& record) {
  robot_time_s_.store(record.state.time_s, std::memory_order_relaxed);
  latest_tick_.store(record.tick, std::memory_order_relaxed);
  const HighLevelStatus& status = record.high_level.status;
  const PublishDue due = schedule_.on_tick(record.tick, status);
  if (due.any() && telemetry_.try_push(Telemetry{due, record.tick, status, record.state})) {
    counts_.feedback_queued.add();
  }
}

HighLevelInterfaceCounters LcmHighLevelAdapter::counters() const {
  HighLevelInterfaceCounters c = counts_;
  c.telemetry_dropped = telemetry_.dropped();
  return c;
}

void LcmHighLevelAdapter::step() {
  // everything that arrived, then what the loop queued
  handle_pending(*command_lcm_, 1);
  release_due(link_faults_.load(), wall_seconds(),
              [this](const std::uint8_t* data, std::size_t size) { handle_command(data, size); });
  drain();
  keep_response_alive();
  log_refusals();
  log_counts_once_per_second();
}

void LcmHighLevelAdapter::drain() {
  while (std::optional<Telemetry> telemetry = telemetry_.try_pop()) publish(*telemetry);
}

void LcmHighLevelAdapter::on_command(const lcm::ReceiveBuffer* buffer, const std::string&) {
  receive_through(link_faults_.load(), static_cast<const std::uint8_t*>(buffer->data), buffer->data_size,
                  wall_seconds(), [this](const std::uint8_t* data, std::size_t size) { handle_command(data, size); });
}

void LcmHighLevelAdapter::handle_command(const std::uint8_t* data, std::size_t size) {
  HighLevelCommand command;
  switch (decode_robot_control_cmd(data, size, command)) {
    case WireDecode::Ok:
      port_.submit(command, robot_time_s_.load(std::memory_order_relaxed));
      counts_.commands_submitted.add();
      return;
    case WireDecode::WrongFingerprint: counts_.wrong_fingerprint.add(); return;
    case WireDecode::Truncated: counts_.truncated.add(); return;
    case WireDecode::Oversized: counts_.oversized.add(); return;
  }
}

void LcmHighLevelAdapter::on_gait_file(const lcm::ReceiveBuffer* buffer, const std::string&) {
  std::string text;
  const WireDecode decoded = decode_file_send(buffer->data, buffer->data_size, text);
  bool accepted = false;
  std::string line;
  if (decoded != WireDecode::Ok) {
    line = "user_gait_file refused (result 1): " + std::string(to_string(decoded)) + " packet of " +
           std::to_string(buffer->data_size) + " bytes";
  } else {
    const UserGaitUploadResult result = user_gaits_.receive(text);
    accepted = result.accepted;
    line = (accepted ? "user_gait_file stored (result 0), " : "user_gait_file refused (result 1): ") + result.detail;
  }
  gait_file_log_.line(wall_seconds(), line);
  (accepted ? counts_.gait_files_accepted : counts_.gait_files_refused).add();
  const file_recv_lcmt reply = make_file_result(accepted);
  command_lcm_->publish(kUserGaitResultChannel, &reply);
}

void LcmHighLevelAdapter::publish(const Telemetry& telemetry) {
  if (telemetry.due.response) publish_response(telemetry.status, telemetry.tick);
  if (telemetry.due.odometry) {
    const localization_lcmt odometry = make_localization(telemetry.state);
    odometry_lcm_->publish(kOdometryChannel, &odometry);
    counts_.odometry_published.add();
  }
  if (telemetry.due.temperature) {
    const danger_states_lcmt temperature = make_danger_states(telemetry.state);
    response_lcm_->publish(kTemperatureChannel, &temperature);
    counts_.temperatures_published.add();
  }
  counts_.feedback_sent.add();
}

void LcmHighLevelAdapter::publish_response(const HighLevelStatus& status, std::uint64_t tick) {
  const robot_control_response_lcmt response = make_response(status);
  response_lcm_->publish(kResponseChannel, &response);
  counts_.responses_published.add();
  last_status_ = status;
  has_status_ = true;
  last_response_tick_ = tick;
  last_response_wall_s_ = wall_seconds();
}

void LcmHighLevelAdapter::keep_response_alive() {
  // a slowly paced loop still ticks: clients must not see a pause above 200 ms
  if (keepalive_s_ <= 0.0 || !has_status_) return;
  const std::uint64_t tick = latest_tick_.load(std::memory_order_relaxed);
  if (tick == last_response_tick_ || wall_seconds() - last_response_wall_s_ < keepalive_s_) return;
  publish_response(last_status_, tick);
}

void LcmHighLevelAdapter::log_refusals() {
  const double now_s = wall_seconds();
  refusal_log_.tick(now_s);
  gait_file_log_.tick(now_s);
  while (std::optional<ClientNote> note = port_.next_note()) {
    char line[256];
    if (note->clamped) {
      std::snprintf(line, sizeof line, "clamped mode %d gait %d (taken): %s", note->mode, note->gait_id, note->reason);
    } else if (note->holder != nullptr) {
      std::snprintf(line, sizeof line, "refused mode %d gait %d while in mode %d (switch_status 5 BAN_TRANS): %s (%s)",
                    note->mode, note->gait_id, note->from_mode, note->reason, note->holder);
    } else {
      std::snprintf(line, sizeof line, "refused mode %d gait %d while in mode %d (switch_status 5 BAN_TRANS): %s",
                    note->mode, note->gait_id, note->from_mode, note->reason);
    }
    refusal_log_.line(now_s, line);
  }
}

LcmHighLevelAdapter::LoggedCounts LcmHighLevelAdapter::current_counts() const {
  const ClientCounters& client = port_.counters();
  LoggedCounts c;
  c.wrong_fingerprint = counts_.wrong_fingerprint.load();
  c.truncated = counts_.truncated.load();
  c.oversized = counts_.oversized.load();
  c.non_finite = client.rejected_non_finite.load();
  c.queue_full = client.queue_full.load();
  const SourceInputCounters& input = port_.input_counters();
  c.ring_overflow = input.ring_overflow.load();
  c.wrong_thread = input.wrong_thread.load();
  c.timeouts = client.timeouts.load();
  c.telemetry_dropped = telemetry_.dropped();
  return c;
}

void LcmHighLevelAdapter::log_counts_once_per_second() {
  if (!count_log_period_.due(wall_seconds())) return;
  const LoggedCounts now = current_counts();
  const LoggedCounts& before = logged_counts_;
  std::string text;
  append_count(text, now.wrong_fingerprint - before.wrong_fingerprint, "with a wrong fingerprint");
  append_count(text, now.truncated - before.truncated, "truncated");
  append_count(text, now.oversized - before.oversized, "oversized");
  append_count(text, now.non_finite - before.non_finite, "with NaN/Inf");
  append_count(text, now.queue_full - before.queue_full, "timed commands beyond the full queue");
  append_count(text, now.ring_overflow - before.ring_overflow, "arriving faster than the loop takes them");
  append_count(text, now.wrong_thread - before.wrong_thread,
               "handed over by a second thread (a defect: one thread per client)");
  if (!text.empty()) {
    std::fprintf(log_, "highlevel: robot_control_cmd packets rejected in the last second: %s\n", text.c_str());
  }
  if (now.timeouts != before.timeouts) {
    std::fprintf(log_,
                 "highlevel: no robot_control_cmd for 0.5 s from the client holding the robot: get-down "
                 "protection (PureDamper, or Off when Off); %llu times so far\n",
                 static_cast<unsigned long long>(now.timeouts));
  }
  if (now.telemetry_dropped != before.telemetry_dropped) {
    std::fprintf(log_, "highlevel: %llu feedback cycles dropped (the interface thread fell behind)\n",
                 static_cast<unsigned long long>(now.telemetry_dropped - before.telemetry_dropped));
  }
  std::fflush(log_);
  logged_counts_ = now;
}

void LcmHighLevelAdapter::finish(std::FILE* out) {
  thread_.stop();
  log_refusals();
  const HighLevelInterfaceCounters c = counters();
  const ClientCounters& m = port_.counters();
  using ull = unsigned long long;
  std::fprintf(out,
               "highlevel: robot_control_cmd %llu received (%llu new commands), %llu refused (BAN_TRANS), "
               "%llu non-finite, %llu queue full, %llu wrong fingerprint, %llu truncated, %llu oversized; "
               "%llu timeouts; published %llu responses, %llu odometry, %llu temperatures; user gait files "
               "%llu stored, %llu refused; %llu feedback cycles dropped\n",
               ull(c.commands_submitted), ull(m.new_commands.load()), ull(m.banned_transitions.load()),
               ull(m.rejected_non_finite.load()), ull(m.queue_full.load()), ull(c.wrong_fingerprint), ull(c.truncated),
               ull(c.oversized), ull(m.timeouts.load()), ull(c.responses_published), ull(c.odometry_published),
               ull(c.temperatures_published), ull(c.gait_files_accepted), ull(c.gait_files_refused),
               ull(c.telemetry_dropped));
  std::fflush(out);
}

}  // namespace cerebellum
