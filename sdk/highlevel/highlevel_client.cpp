#include "cerebellum/highlevel_client.hpp"

#include <lcm/lcm-cpp.hpp>
#include <poll.h>

#include <array>

namespace cerebellum {
namespace {

constexpr const char* kCommandChannel = "robot_control_cmd";
constexpr const char* kResponseChannel = "robot_control_response";
constexpr const char* kTemperatureChannel = "motor_temperature";
constexpr const char* kOdometryChannel = "global_to_robot";
constexpr int kFinishedPercent = 95;
constexpr int kBanTransition = 5;
// responses after a send() before a BAN_TRANS is taken as the answer to it
constexpr std::uint64_t kResponsesBeforeRefusal = 3;
constexpr std::chrono::milliseconds kMaxHeartbeatPeriod{100};
constexpr int kPollTimeoutMs = 20;

template <typename Message>
std::optional<Message> decode(const lcm::ReceiveBuffer* buffer) {
  Message message{};
  if (message.decode(buffer->data, 0, static_cast<int>(buffer->data_size)) != static_cast<int>(buffer->data_size)) {
    return std::nullopt;
  }
  return message;
}

}  // namespace

const char* to_string(HighLevelClientStatus status) {
  switch (status) {
    case HighLevelClientStatus::Ok: return "ok";
    case HighLevelClientStatus::NotRunning: return "not running";
    case HighLevelClientStatus::TransportError: return "transport error";
    case HighLevelClientStatus::Timeout: return "timeout";
    case HighLevelClientStatus::Refused: return "refused (BAN_TRANS)";
    case HighLevelClientStatus::InvalidArgument: return "invalid argument";
  }
  return "?";
}

HighLevelClient::HighLevelClient() : HighLevelClient(HighLevelClientOptions{}) {}

HighLevelClient::HighLevelClient(const HighLevelClientOptions& options) : options_(options) {}

HighLevelClient::~HighLevelClient() { stop(); }

HighLevelClientStatus HighLevelClient::start() {
  if (running_.load()) return HighLevelClientStatus::Ok;
  if (options_.heartbeat_period <= std::chrono::milliseconds::zero() ||
      options_.heartbeat_period > kMaxHeartbeatPeriod) {
    const std::lock_guard lock(feedback_mutex_);
    last_error_ = "heartbeat_period must be in (0, 100] ms, got " + std::to_string(options_.heartbeat_period.count());
    return HighLevelClientStatus::InvalidArgument;
  }
  for (const auto& [url, lcm] :
       {std::pair{&options_.command_url, &command_lcm_}, std::pair{&options_.response_url, &response_lcm_},
        std::pair{&options_.odometry_url, &odometry_lcm_}}) {
    *lcm = std::make_unique<lcm::LCM>(*url);
    if (!(*lcm)->good()) {
      const std::lock_guard lock(feedback_mutex_);
      last_error_ = "cannot open LCM url " + *url + " (is there a multicast route?)";
      return HighLevelClientStatus::TransportError;
    }
  }
  response_lcm_->subscribe(kResponseChannel, &HighLevelClient::on_response, this);
  response_lcm_->subscribe(kTemperatureChannel, &HighLevelClient::on_temperature, this);
  odometry_lcm_->subscribe(kOdometryChannel, &HighLevelClient::on_odometry, this);
  {
    const std::lock_guard lock(command_mutex_);
    has_command_ = false;
  }
  running_.store(true);
  receiver_ = std::thread([this] { receive_loop(); });
  heartbeat_ = std::thread([this] { heartbeat_loop(); });
  return HighLevelClientStatus::Ok;
}

void HighLevelClient::stop() {
  {
    const std::lock_guard command_lock(command_mutex_);
    const std::lock_guard feedback_lock(feedback_mutex_);
    running_.store(false);
  }
  heartbeat_wake_.notify_all();
  feedback_changed_.notify_all();
  if (heartbeat_.joinable()) heartbeat_.join();
  if (receiver_.joinable()) receiver_.join();
}

bool HighLevelClient::publish_locked(const robot_control_cmd_lcmt& command) {
  if (command_lcm_->publish(kCommandChannel, &command) == 0) return true;
  const std::lock_guard lock(feedback_mutex_);
  last_error_ = "publishing robot_control_cmd on " + options_.command_url + " failed";
  return false;
}

HighLevelClientStatus HighLevelClient::send(const robot_control_cmd_lcmt& command) {
  const std::lock_guard lock(command_mutex_);
  if (!running_.load()) return HighLevelClientStatus::NotRunning;
  if (!has_command_) {
    // make the MC's stored life_count ours, so the command below is new for it
    robot_control_cmd_lcmt sync{};
    sync.mode = -1;
    sync.life_count = life_count_;
    if (!publish_locked(sync)) return HighLevelClientStatus::TransportError;
  }
  life_count_ = static_cast<std::int8_t>(life_count_ + 1);
  last_command_ = command;
  last_command_.life_count = life_count_;
  has_command_ = true;
  responses_at_send_ = responses_received();
  return publish_locked(last_command_) ? HighLevelClientStatus::Ok : HighLevelClientStatus::TransportError;
}

HighLevelClientStatus HighLevelClient::wait_for_mode(int mode, std::optional<int> gait_id,
                                                     std::chrono::milliseconds timeout) {
  std::uint64_t responses_at_send = 0;
  {
    const std::lock_guard lock(command_mutex_);
    responses_at_send = responses_at_send_;
  }
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  std::unique_lock lock(feedback_mutex_);
  while (true) {
    if (!running_.load()) return HighLevelClientStatus::NotRunning;
    if (response_) {
      const robot_control_response_lcmt& r = *response_;
      const bool reached =
          r.mode == mode && (!gait_id || r.gait_id == *gait_id) && r.order_process_bar >= kFinishedPercent;
      if (reached) return HighLevelClientStatus::Ok;
      if (r.switch_status == kBanTransition && responses_ >= responses_at_send + kResponsesBeforeRefusal) {
        return HighLevelClientStatus::Refused;
      }
    }
    if (feedback_changed_.wait_until(lock, deadline) == std::cv_status::timeout &&
        std::chrono::steady_clock::now() >= deadline) {
      return HighLevelClientStatus::Timeout;
    }
  }
}

std::optional<robot_control_response_lcmt> HighLevelClient::latest_response() const {
  const std::lock_guard lock(feedback_mutex_);
  return response_;
}

std::optional<localization_lcmt> HighLevelClient::latest_odometry() const {
  const std::lock_guard lock(feedback_mutex_);
  return odometry_;
}

std::optional<danger_states_lcmt> HighLevelClient::latest_temperature() const {
  const std::lock_guard lock(feedback_mutex_);
  return temperature_;
}

std::uint64_t HighLevelClient::responses_received() const {
  const std::lock_guard lock(feedback_mutex_);
  return responses_;
}

std::int8_t HighLevelClient::life_count() const {
  const std::lock_guard lock(command_mutex_);
  return life_count_;
}

std::string HighLevelClient::last_error() const {
  const std::lock_guard lock(feedback_mutex_);
  return last_error_;
}

void HighLevelClient::receive_loop() {
  std::array<pollfd, 2> fds{};
  fds[0] = {response_lcm_->getFileno(), POLLIN, 0};
  fds[1] = {odometry_lcm_->getFileno(), POLLIN, 0};
  while (running_.load()) {
    if (poll(fds.data(), fds.size(), kPollTimeoutMs) <= 0) continue;
    if (fds[0].revents & POLLIN) response_lcm_->handle();
    if (fds[1].revents & POLLIN) odometry_lcm_->handle();
  }
}

void HighLevelClient::heartbeat_loop() {
  std::unique_lock lock(command_mutex_);
  while (running_.load()) {
    heartbeat_wake_.wait_for(lock, options_.heartbeat_period, [this] { return !running_.load(); });
    if (running_.load() && has_command_) publish_locked(last_command_);
  }
}

void HighLevelClient::on_response(const lcm::ReceiveBuffer* buffer, const std::string&) {
  const std::optional<robot_control_response_lcmt> message = decode<robot_control_response_lcmt>(buffer);
  if (!message) return;
  {
    const std::lock_guard lock(feedback_mutex_);
    response_ = message;
    ++responses_;
  }
  feedback_changed_.notify_all();
}

void HighLevelClient::on_odometry(const lcm::ReceiveBuffer* buffer, const std::string&) {
  const std::optional<localization_lcmt> message = decode<localization_lcmt>(buffer);
  if (!message) return;
  const std::lock_guard lock(feedback_mutex_);
  odometry_ = message;
}

void HighLevelClient::on_temperature(const lcm::ReceiveBuffer* buffer, const std::string&) {
  const std::optional<danger_states_lcmt> message = decode<danger_states_lcmt>(buffer);
  if (!message) return;
  const std::lock_guard lock(feedback_mutex_);
  temperature_ = message;
}

}  // namespace cerebellum
