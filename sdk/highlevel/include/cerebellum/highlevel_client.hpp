// A thin C++ client of the CyberDog2 high-level LCM interface (robot_control_cmd and friends),
// for cerebellum or a real CyberDog2. One verb per call; the hot calls return a status, never throw.
//
//   cerebellum::HighLevelClient client;
//   if (client.start() != cerebellum::HighLevelClientStatus::Ok) ...  // client.last_error()
//   robot_control_cmd_lcmt stand{};
//   stand.mode = 12;
//   client.send(stand);                                               // new life_count, heartbeat
//   client.wait_for_mode(12, std::nullopt, std::chrono::seconds(10)); // mode 12, bar >= 95
//
// After the first send() a heartbeat thread repeats the last command (same life_count) so the MC's
// 0.5 s timeout never trips; stop() (or the destructor) ends it, and the MC lies down 0.5 s later.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "danger_states_lcmt.hpp"
#include "localization_lcmt.hpp"
#include "robot_control_cmd_lcmt.hpp"
#include "robot_control_response_lcmt.hpp"

namespace lcm {
class LCM;
struct ReceiveBuffer;
}  // namespace lcm

namespace cerebellum {

struct HighLevelClientOptions {
  std::string command_url = "udpm://239.255.76.67:7671?ttl=255";   // robot_control_cmd
  std::string response_url = "udpm://239.255.76.67:7670?ttl=255";  // robot_control_response, motor_temperature
  std::string odometry_url = "udpm://239.255.76.67:7667?ttl=255";  // global_to_robot
  // how often the last command is repeated; at most 100 ms (the interface wants >= 10 Hz)
  std::chrono::milliseconds heartbeat_period{50};
};

enum class HighLevelClientStatus {
  Ok,
  NotRunning,       // start() has not succeeded, or stop() was called
  TransportError,   // LCM could not open a url or publish (last_error() says which)
  Timeout,          // the wanted state was not reported in time
  Refused,          // the MC answers BAN_TRANS: the command is not allowed or not available
  InvalidArgument,  // a heartbeat period outside (0, 100] ms
};
const char* to_string(HighLevelClientStatus status);

class HighLevelClient {
 public:
  HighLevelClient();
  explicit HighLevelClient(const HighLevelClientOptions& options);
  ~HighLevelClient();
  HighLevelClient(const HighLevelClient&) = delete;
  HighLevelClient& operator=(const HighLevelClient&) = delete;

  // opens the urls and starts the receive and heartbeat threads
  HighLevelClientStatus start();
  // publishes command with a new life_count (the given one is ignored) and makes it the heartbeat.
  // The first send() is preceded by a mode -1 message, which the MC ignores except for its
  // life_count, so the command counts as new whatever an earlier client left behind.
  HighLevelClientStatus send(const robot_control_cmd_lcmt& command);
  // until the response reports mode (and gait_id, when given) with order_process_bar >= 95.
  // Refused when BAN_TRANS is still reported in the third response after the last send().
  HighLevelClientStatus wait_for_mode(int mode, std::optional<int> gait_id, std::chrono::milliseconds timeout);

  std::optional<robot_control_response_lcmt> latest_response() const;
  std::optional<localization_lcmt> latest_odometry() const;
  std::optional<danger_states_lcmt> latest_temperature() const;
  std::uint64_t responses_received() const;
  // the life_count of the last command sent
  std::int8_t life_count() const;
  std::string last_error() const;

  // stops the heartbeat and the threads; idempotent
  void stop();

 private:
  void receive_loop();
  void heartbeat_loop();
  bool publish_locked(const robot_control_cmd_lcmt& command);
  void on_response(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void on_odometry(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void on_temperature(const lcm::ReceiveBuffer* buffer, const std::string& channel);

  HighLevelClientOptions options_;
  std::unique_ptr<lcm::LCM> command_lcm_;
  std::unique_ptr<lcm::LCM> response_lcm_;
  std::unique_ptr<lcm::LCM> odometry_lcm_;
  std::atomic<bool> running_{false};

  // the command side: last command, its life_count, the heartbeat
  mutable std::mutex command_mutex_;
  std::condition_variable heartbeat_wake_;
  robot_control_cmd_lcmt last_command_{};
  bool has_command_ = false;
  std::int8_t life_count_ = 0;
  std::uint64_t responses_at_send_ = 0;

  // the feedback side
  mutable std::mutex feedback_mutex_;
  std::condition_variable feedback_changed_;
  std::optional<robot_control_response_lcmt> response_;
  std::optional<localization_lcmt> odometry_;
  std::optional<danger_states_lcmt> temperature_;
  std::uint64_t responses_ = 0;
  std::string last_error_;

  std::thread receiver_;
  std::thread heartbeat_;
};

}  // namespace cerebellum
