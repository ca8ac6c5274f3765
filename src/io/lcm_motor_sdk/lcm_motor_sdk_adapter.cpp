#include "io/lcm_motor_sdk/lcm_motor_sdk_adapter.hpp"

#include <lcm/lcm-cpp.hpp>

#include <string>

#include "io/common/wall_clock.hpp"
#include "io/lcm_common/lcm_url.hpp"
#include "io/lcm_motor_sdk/motor_sdk_wire.hpp"

namespace cerebellum {
namespace {

constexpr const char* kInterfaceName = "motor sdk";

template <typename Message>
void publish_message(lcm::LCM& lcm, const char* channel, const Message& message) {
  lcm.publish(channel, &message);
}

}  // namespace

LcmMotorSdkAdapter::LcmMotorSdkAdapter(const MotorSdkConfig& config, std::FILE* log)
    : source_(config.parameters),
      log_(log),
      control_lcm_(open_lcm_url(config.control_url, kInterfaceName)),
      count_log_period_(wall_seconds()) {
  control_lcm_->subscribe(kMotorCtrlChannel, &LcmMotorSdkAdapter::on_motor_ctrl, this);
  thread_.start([this] { step(); }, [this] { drain(); });
}

LcmMotorSdkAdapter::~LcmMotorSdkAdapter() { thread_.stop(); }

void LcmMotorSdkAdapter::on_cycle(const CycleRecord& record) {
  robot_time_s_.store(record.state.time_s, std::memory_order_relaxed);
  telemetry_.try_push(Telemetry{record, source_.status()});
}

MotorCtrlRejections LcmMotorSdkAdapter::rejections() const {
  MotorCtrlRejections r;
  r.wrong_fingerprint = wrong_fingerprint_.load(std::memory_order_relaxed);
  r.truncated = truncated_.load(std::memory_order_relaxed);
  r.oversized = oversized_.load(std::memory_order_relaxed);
  r.non_finite = source_.counters().frames_non_finite;
  return r;
}

void LcmMotorSdkAdapter::step() {
  handle_pending(*control_lcm_, 1);
  release_due(link_faults_.load(), wall_seconds(),
              [this](const std::uint8_t* data, std::size_t size) { handle_motor_ctrl(data, size); });
  while (std::optional<Telemetry> telemetry = telemetry_.try_pop()) {
    publish(*telemetry);
    log_changes(telemetry->status);
  }
  log_counts_once_per_second();
}

void LcmMotorSdkAdapter::drain() {
  while (std::optional<Telemetry> telemetry = telemetry_.try_pop()) publish(*telemetry);
}

void LcmMotorSdkAdapter::on_motor_ctrl(const lcm::ReceiveBuffer* buffer, const std::string&) {
  receive_through(link_faults_.load(), static_cast<const std::uint8_t*>(buffer->data), buffer->data_size,
                  wall_seconds(),
                  [this](const std::uint8_t* data, std::size_t size) { handle_motor_ctrl(data, size); });
}

void LcmMotorSdkAdapter::handle_motor_ctrl(const std::uint8_t* data, std::size_t size) {
  JointCommand frame;
  switch (decode_motor_ctrl(data, size, frame)) {
    case WireDecode::Ok: source_.mailbox().push(frame, robot_time_s_.load(std::memory_order_relaxed)); return;
    case WireDecode::WrongFingerprint: wrong_fingerprint_.fetch_add(1, std::memory_order_relaxed); return;
    case WireDecode::Truncated: truncated_.fetch_add(1, std::memory_order_relaxed); return;
    case WireDecode::Oversized: oversized_.fetch_add(1, std::memory_order_relaxed); return;
  }
}

void LcmMotorSdkAdapter::publish(const Telemetry& telemetry) {
  // state_estimator and leg_control_data belong to LcmStateFeedback (once for both interfaces)
  if (!telemetry.status.motor_mode) return;
  publish_message(*control_lcm_, kSpiDataChannel, make_spi_data(telemetry.record.state));
  publish_message(*control_lcm_, kMotorCtrlStateChannel, make_motor_ctrl_state(telemetry.status));
}

void LcmMotorSdkAdapter::log_changes(const MotorSdkStatus& status) {
  const char* message = nullptr;
  const bool was_lost = last_status_.err_flag & kMotorSdkCommandLost;
  const bool is_lost = status.err_flag & kMotorSdkCommandLost;
  if (status.motor_mode && !last_status_.motor_mode) {
    message = "motor mode entered; err_flag 0x02 until all-zero frames activate it";
  } else if (is_lost && !was_lost) {
    message =
        "err_flag 0x02: communication lost over 500 ms; damping, the robot lies down; send all-zero "
        "frames to recover";
  } else if (!is_lost && was_lost && status.motor_mode) {
    message = "err_flag bit 1 cleared by all-zero frames; commands are executed";
  }
  last_status_ = status;
  if (message != nullptr) std::fprintf(log_, "motor sdk: %s\n", message);
  if (!refusal_logged_ && source_.last_refusal_holder() != nullptr) {
    refusal_logged_ = true;
    message = source_.last_refusal_holder();
    std::fprintf(log_,
                 "motor sdk: motor_ctrl refused: %s has the robot (motor mode is entered only from Off or "
                 "PureDamper: mc.startup off or damper)\n",
                 message);
  }
  if (message != nullptr) std::fflush(log_);
}

void LcmMotorSdkAdapter::log_counts_once_per_second() {
  if (!count_log_period_.due(wall_seconds())) return;
  const Counts now{source_.counters(), rejections()};
  const Counts& before = logged_counts_;
  std::string text;
  append_count(text, now.rejected.wrong_fingerprint - before.rejected.wrong_fingerprint, "with a wrong fingerprint");
  append_count(text, now.rejected.truncated - before.rejected.truncated, "truncated");
  append_count(text, now.rejected.oversized - before.rejected.oversized, "oversized");
  append_count(text, now.rejected.non_finite - before.rejected.non_finite, "with NaN/Inf");
  append_count(text, now.source.frames_dropped - before.source.frames_dropped, "dropped (mailbox full)");
  if (!text.empty())
    std::fprintf(log_, "motor sdk: motor_ctrl packets rejected in the last second: %s\n", text.c_str());
  text.clear();
  append_count(text, now.source.clamped_gains - before.source.clamped_gains, "kp/kd");
  append_count(text, now.source.clamped_velocities - before.source.clamped_velocities, "qd_des");
  append_count(text, now.source.clamped_torques - before.source.clamped_torques, "tau_des");
  append_count(text, now.source.clamped_positions - before.source.clamped_positions, "q_des at a joint limit");
  append_count(text, now.source.clamped_jumps - before.source.clamped_jumps, "q_des jumps");
  append_count(text, now.source.frames_ignored_while_lost - before.source.frames_ignored_while_lost,
               "non-zero frames ignored while err_flag bit 1 is set");
  if (!text.empty()) std::fprintf(log_, "motor sdk: joint values clamped in the last second: %s\n", text.c_str());
  std::fflush(log_);
  logged_counts_ = now;
}

void LcmMotorSdkAdapter::finish(std::FILE* out) {
  thread_.stop();
  const MotorSdkCounters c = source_.counters();
  const MotorCtrlRejections r = rejections();
  using ull = unsigned long long;
  std::fprintf(out,
               "motor sdk: motor mode %s, err_flag 0x%02x; frames %llu accepted, %llu refused, %llu ignored while "
               "lost; rejected %llu wrong fingerprint, %llu truncated, %llu oversized, %llu non-finite, %llu "
               "mailbox full; clamped %llu kp/kd, %llu qd_des, %llu tau_des, %llu q_des limits, %llu jumps; "
               "%llu communication losses; %llu telemetry records dropped\n",
               last_status_.motor_mode ? "yes" : "no", static_cast<unsigned>(last_status_.err_flag),
               ull(c.frames_accepted), ull(c.frames_refused), ull(c.frames_ignored_while_lost),
               ull(r.wrong_fingerprint), ull(r.truncated), ull(r.oversized), ull(r.non_finite), ull(c.frames_dropped),
               ull(c.clamped_gains), ull(c.clamped_velocities), ull(c.clamped_torques), ull(c.clamped_positions),
               ull(c.clamped_jumps), ull(c.commands_lost), ull(telemetry_dropped()));
  std::fflush(out);
}

}  // namespace cerebellum
