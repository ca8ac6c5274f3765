#include "io/lcm_highlevel/lcm_highlevel_adapter.hpp"

#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <stdexcept>

#include "io/lcm_highlevel/highlevel_wire.hpp"
#include "io/lcm_highlevel/user_gait_file.hpp"

namespace cerebellum {
namespace {

constexpr const char* kCommandChannel = "robot_control_cmd";
constexpr const char* kGaitFileChannel = "user_gait_file";
constexpr const char* kGaitResultChannel = "user_gait_result";
constexpr const char* kResponseChannel = "robot_control_response";
constexpr const char* kTemperatureChannel = "motor_temperature";
constexpr const char* kOdometryChannel = "global_to_robot";
constexpr int kRefusalLinesPerSecond = 5;

std::unique_ptr<lcm::LCM> open_lcm(const std::string& url) {
  auto lcm = std::make_unique<lcm::LCM>(url);
  if (!lcm->good()) {
    throw std::runtime_error("highlevel: cannot open LCM url " + url +
                             " (is there a multicast route? see docs/highlevel.md)");
  }
  return lcm;
}

double wall_seconds() {
  using Clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
}

// appends "<count> <what>" when count is not zero
void describe(std::string& text, std::uint64_t count, const char* what) {
  if (count == 0) return;
  text += (text.empty() ? "" : ", ") + std::to_string(count) + " " + what;
}

std::string describe_gait_file(const UserGaitFile& file) {
  if (file.kind == UserGaitFile::Kind::Definition) {
    int units = 0;
    for (const GaitSection& section : file.definition.sections) units += section.duration_units;
    char text[96];
    std::snprintf(text, sizeof text, "gait definition: %zu sections, %.2f s", file.definition.sections.size(),
                  units * kGaitSectionUnitS);
    return text;
  }
  long duration_ms = 0;
  for (const HighLevelCommand& step : file.parameters.steps) duration_ms += step.duration;
  return "gait parameters: " + std::to_string(file.parameters.steps.size()) + " steps, " +
         std::to_string(duration_ms) + " ms";
}

}  // namespace

LcmHighLevelAdapter::LcmHighLevelAdapter(HighLevelMachine& machine, const HighLevelLcmConfig& config,
                                         double loop_period_s, std::FILE* log)
    : machine_(machine), log_(log), keepalive_s_(config.response_keepalive_s),
      command_lcm_(open_lcm(config.command_url)), response_lcm_(open_lcm(config.response_url)),
      odometry_lcm_(open_lcm(config.odometry_url)), schedule_(loop_period_s) {
  command_lcm_->subscribe(kCommandChannel, &LcmHighLevelAdapter::on_command, this);
  command_lcm_->subscribe(kGaitFileChannel, &LcmHighLevelAdapter::on_gait_file, this);
  std::fprintf(log_, "highlevel: robot_control_cmd and user_gait_file on %s; robot_control_response and "
               "motor_temperature on %s; global_to_robot on %s\n",
               config.command_url.c_str(), config.response_url.c_str(), config.odometry_url.c_str());
  std::fflush(log_);
  next_count_log_s_ = wall_seconds() + 1.0;
  thread_ = std::thread([this] { run(); });
}

LcmHighLevelAdapter::~LcmHighLevelAdapter() {
  running_.store(false);
  if (thread_.joinable()) thread_.join();
}

void LcmHighLevelAdapter::on_cycle(const CycleRecord& record) {
  robot_time_s_.store(record.state.time_s, std::memory_order_relaxed);
  latest_tick_.store(record.tick, std::memory_order_relaxed);
  const HighLevelStatus& status = machine_.status();
  const PublishDue due = schedule_.on_tick(record.tick, status);
  if (due.any() && telemetry_.try_push(Telemetry{due, record.tick, status, record.state})) {
    feedback_queued_.fetch_add(1, std::memory_order_release);
  }
}

HighLevelInterfaceCounters LcmHighLevelAdapter::counters() const {
  HighLevelInterfaceCounters c;
  c.commands_submitted = commands_submitted_.load();
  c.wrong_fingerprint = wrong_fingerprint_.load();
  c.truncated = truncated_.load();
  c.oversized = oversized_.load();
  c.responses_published = responses_published_.load();
  c.odometry_published = odometry_published_.load();
  c.temperatures_published = temperatures_published_.load();
  c.gait_files_accepted = gait_files_accepted_.load();
  c.gait_files_refused = gait_files_refused_.load();
  c.feedback_queued = feedback_queued_.load(std::memory_order_acquire);
  c.feedback_sent = feedback_sent_.load(std::memory_order_acquire);
  c.telemetry_dropped = telemetry_.dropped();
  return c;
}

void LcmHighLevelAdapter::run() {
  while (running_.load()) {
    // everything that arrived, then what the loop queued
    if (command_lcm_->handleTimeout(1) > 0) {
      while (command_lcm_->handleTimeout(0) > 0) {
      }
    }
    while (std::optional<Telemetry> telemetry = telemetry_.try_pop()) publish(*telemetry);
    keep_response_alive();
    log_refusals();
    log_counts_once_per_second();
  }
  while (std::optional<Telemetry> telemetry = telemetry_.try_pop()) publish(*telemetry);
}

void LcmHighLevelAdapter::on_command(const lcm::ReceiveBuffer* buffer, const std::string&) {
  HighLevelCommand command;
  switch (decode_robot_control_cmd(buffer->data, buffer->data_size, command)) {
    case WireDecode::Ok:
      machine_.submit(command, robot_time_s_.load(std::memory_order_relaxed));
      commands_submitted_.fetch_add(1);
      return;
    case WireDecode::WrongFingerprint: wrong_fingerprint_.fetch_add(1, std::memory_order_relaxed); return;
    case WireDecode::Truncated: truncated_.fetch_add(1, std::memory_order_relaxed); return;
    case WireDecode::Oversized: oversized_.fetch_add(1, std::memory_order_relaxed); return;
  }
}

void LcmHighLevelAdapter::on_gait_file(const lcm::ReceiveBuffer* buffer, const std::string&) {
  std::string text;
  const WireDecode decoded = decode_file_send(buffer->data, buffer->data_size, text);
  bool accepted = false;
  if (decoded != WireDecode::Ok) {
    std::fprintf(log_, "highlevel: user_gait_file refused (result 1): %s packet of %u bytes\n", to_string(decoded),
                 buffer->data_size);
  } else if (const UserGaitParse parsed = parse_user_gait_file(text); !parsed.file) {
    std::fprintf(log_, "highlevel: user_gait_file refused (result 1): %s (user gaits not supported yet beyond "
                 "storing a valid file)\n", parsed.error.c_str());
  } else {
    accepted = true;
    user_gaits_.store(*parsed.file);
    std::fprintf(log_, "highlevel: user_gait_file stored (result 0), %s; running user gaits (11/110, 62/110) is "
                 "not supported yet\n", describe_gait_file(*parsed.file).c_str());
  }
  std::fflush(log_);
  (accepted ? gait_files_accepted_ : gait_files_refused_).fetch_add(1);
  const file_recv_lcmt reply = make_file_result(accepted);
  command_lcm_->publish(kGaitResultChannel, &reply);
}

void LcmHighLevelAdapter::publish(const Telemetry& telemetry) {
  if (telemetry.due.response) publish_response(telemetry.status, telemetry.tick);
  if (telemetry.due.odometry) {
    const localization_lcmt odometry = make_localization(telemetry.state);
    odometry_lcm_->publish(kOdometryChannel, &odometry);
    odometry_published_.fetch_add(1);
  }
  if (telemetry.due.temperature) {
    const danger_states_lcmt temperature = make_danger_states(telemetry.state);
    response_lcm_->publish(kTemperatureChannel, &temperature);
    temperatures_published_.fetch_add(1);
  }
  feedback_sent_.fetch_add(1, std::memory_order_release);
}

void LcmHighLevelAdapter::publish_response(const HighLevelStatus& status, std::uint64_t tick) {
  const robot_control_response_lcmt response = make_response(status);
  response_lcm_->publish(kResponseChannel, &response);
  responses_published_.fetch_add(1);
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
  if (now_s - refusal_window_start_s_ >= 1.0) {
    if (refusals_suppressed_ > 0) {
      std::fprintf(log_, "highlevel: %llu more refusals (BAN_TRANS) in the last second not shown\n",
                   static_cast<unsigned long long>(refusals_suppressed_));
      std::fflush(log_);
    }
    refusal_window_start_s_ = now_s;
    refusals_in_window_ = 0;
    refusals_suppressed_ = 0;
  }
  while (std::optional<RefusalNote> note = machine_.refusals().try_pop()) {
    if (refusals_in_window_ >= kRefusalLinesPerSecond) {
      ++refusals_suppressed_;
      continue;
    }
    ++refusals_in_window_;
    std::fprintf(log_, "highlevel: refused mode %d gait %d while in mode %d (switch_status 5 BAN_TRANS): %s\n",
                 note->mode, note->gait_id, note->from_mode, note->reason);
    std::fflush(log_);
  }
}

LcmHighLevelAdapter::LoggedCounts LcmHighLevelAdapter::current_counts() const {
  const CommandCounters& machine = machine_.counters();
  LoggedCounts c;
  c.wrong_fingerprint = wrong_fingerprint_.load();
  c.truncated = truncated_.load();
  c.oversized = oversized_.load();
  c.non_finite = machine.rejected_non_finite.load();
  c.queue_full = machine.queue_full.load();
  c.ring_overflow = machine.ring_overflow.load();
  c.timeouts = machine.timeouts.load();
  c.telemetry_dropped = telemetry_.dropped();
  return c;
}

void LcmHighLevelAdapter::log_counts_once_per_second() {
  const double now_s = wall_seconds();
  if (now_s < next_count_log_s_) return;
  next_count_log_s_ = now_s + 1.0;
  const LoggedCounts now = current_counts();
  const LoggedCounts& before = logged_counts_;
  std::string text;
  describe(text, now.wrong_fingerprint - before.wrong_fingerprint, "with a wrong fingerprint");
  describe(text, now.truncated - before.truncated, "truncated");
  describe(text, now.oversized - before.oversized, "oversized");
  describe(text, now.non_finite - before.non_finite, "with NaN/Inf");
  describe(text, now.queue_full - before.queue_full, "timed commands beyond the 64-entry queue");
  describe(text, now.ring_overflow - before.ring_overflow, "arriving faster than the loop takes them");
  if (!text.empty()) {
    std::fprintf(log_, "highlevel: robot_control_cmd packets rejected in the last second: %s\n", text.c_str());
  }
  if (now.timeouts != before.timeouts) {
    std::fprintf(log_, "highlevel: no robot_control_cmd for 0.5 s: get-down protection (PureDamper, or Off when "
                 "Off); %llu times so far\n", static_cast<unsigned long long>(now.timeouts));
  }
  if (now.telemetry_dropped != before.telemetry_dropped) {
    std::fprintf(log_, "highlevel: %llu feedback cycles dropped (the interface thread fell behind)\n",
                 static_cast<unsigned long long>(now.telemetry_dropped - before.telemetry_dropped));
  }
  std::fflush(log_);
  logged_counts_ = now;
}

void LcmHighLevelAdapter::finish(std::FILE* out) {
  running_.store(false);
  if (thread_.joinable()) thread_.join();
  log_refusals();
  const HighLevelInterfaceCounters c = counters();
  const CommandCounters& m = machine_.counters();
  using ull = unsigned long long;
  std::fprintf(out,
               "highlevel: robot_control_cmd %llu received (%llu new commands), %llu refused (BAN_TRANS), "
               "%llu non-finite, %llu queue full, %llu wrong fingerprint, %llu truncated, %llu oversized; "
               "%llu timeouts; published %llu responses, %llu odometry, %llu temperatures; user gait files "
               "%llu stored, %llu refused; %llu feedback cycles dropped\n",
               ull(c.commands_submitted), ull(m.new_commands.load()), ull(m.banned_transitions.load()),
               ull(m.rejected_non_finite.load()), ull(m.queue_full.load()), ull(c.wrong_fingerprint),
               ull(c.truncated), ull(c.oversized), ull(m.timeouts.load()), ull(c.responses_published),
               ull(c.odometry_published), ull(c.temperatures_published), ull(c.gait_files_accepted),
               ull(c.gait_files_refused), ull(c.telemetry_dropped));
  std::fflush(out);
}

}  // namespace cerebellum
