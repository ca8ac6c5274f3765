// The other end of the high-level interface for tests, on the interface's urls: publishes raw
// packets and records every message it receives. Use inside a private network namespace only.
#pragma once

#include <lcm/lcm-cpp.hpp>
#include <poll.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "danger_states_lcmt.hpp"
#include "file_recv_lcmt.hpp"
#include "localization_lcmt.hpp"
#include "robot_control_cmd_lcmt.hpp"
#include "robot_control_response_lcmt.hpp"

namespace cerebellum::test {

using Bytes = std::vector<std::uint8_t>;

// polls condition every millisecond of wall time; false when it is still not true after timeout_s
template <typename Condition>
bool eventually(Condition condition, double timeout_s = 10.0) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (!condition()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

class RawLcmPeer {
 public:
  static constexpr const char* kMarkerChannel = "test_marker";

  RawLcmPeer()
      : command_lcm_("udpm://239.255.76.67:7671?ttl=0"),
        response_lcm_("udpm://239.255.76.67:7670?ttl=0"),
        odometry_lcm_("udpm://239.255.76.67:7667?ttl=0") {
    if (!command_lcm_.good() || !response_lcm_.good() || !odometry_lcm_.good()) {
      throw std::runtime_error("RawLcmPeer: cannot open LCM (run inside scripts/netns_run.sh)");
    }
    command_lcm_.subscribe("robot_control_cmd", &RawLcmPeer::on_message, this);
    command_lcm_.subscribe("user_gait_result", &RawLcmPeer::on_message, this);
    response_lcm_.subscribe("robot_control_response", &RawLcmPeer::on_message, this);
    response_lcm_.subscribe("motor_temperature", &RawLcmPeer::on_message, this);
    odometry_lcm_.subscribe("global_to_robot", &RawLcmPeer::on_message, this);
    command_lcm_.subscribe(kMarkerChannel, &RawLcmPeer::on_message, this);
    thread_ = std::thread([this] { receive(); });
  }
  ~RawLcmPeer() {
    running_.store(false);
    thread_.join();
  }
  RawLcmPeer(const RawLcmPeer&) = delete;
  RawLcmPeer& operator=(const RawLcmPeer&) = delete;

  void publish_command(const Bytes& packet) { publish(command_lcm_, "robot_control_cmd", packet); }
  void publish_gait_file(const Bytes& packet) { publish(command_lcm_, "user_gait_file", packet); }
  void publish_response(const robot_control_response_lcmt& m) { response_lcm_.publish("robot_control_response", &m); }
  void publish_odometry(const localization_lcmt& m) { odometry_lcm_.publish("global_to_robot", &m); }
  void publish_temperature(const danger_states_lcmt& m) { response_lcm_.publish("motor_temperature", &m); }
  // a packet of the peer's own on the command port: once it is back, everything sent to that port
  // before it (by any process on this host) has arrived too
  void publish_marker() { publish(command_lcm_, kMarkerChannel, Bytes{1}); }
  std::size_t markers_seen() const { return count(kMarkerChannel); }

  std::vector<robot_control_cmd_lcmt> commands() const { return decoded<robot_control_cmd_lcmt>("robot_control_cmd"); }
  std::vector<robot_control_response_lcmt> responses() const {
    return decoded<robot_control_response_lcmt>("robot_control_response");
  }
  std::vector<localization_lcmt> odometry() const { return decoded<localization_lcmt>("global_to_robot"); }
  std::vector<danger_states_lcmt> temperatures() const { return decoded<danger_states_lcmt>("motor_temperature"); }
  std::vector<file_recv_lcmt> gait_results() const { return decoded<file_recv_lcmt>("user_gait_result"); }
  std::size_t count(const std::string& channel) const {
    const std::lock_guard lock(mutex_);
    std::size_t n = 0;
    for (const auto& [name, bytes] : received_) n += name == channel;
    return n;
  }

 private:
  static void publish(lcm::LCM& lcm, const std::string& channel, const Bytes& packet) {
    if (lcm.publish(channel, packet.data(), static_cast<unsigned>(packet.size())) != 0) {
      throw std::runtime_error("RawLcmPeer: publish on " + channel + " failed");
    }
  }

  void on_message(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
    const auto* data = static_cast<const std::uint8_t*>(buffer->data);
    const std::lock_guard lock(mutex_);
    received_.emplace_back(channel, Bytes(data, data + buffer->data_size));
  }

  void receive() {
    std::array<lcm::LCM*, 3> lcms{&command_lcm_, &response_lcm_, &odometry_lcm_};
    std::array<pollfd, 3> fds{};
    for (std::size_t i = 0; i < lcms.size(); ++i) fds[i] = {lcms[i]->getFileno(), POLLIN, 0};
    while (running_.load()) {
      if (poll(fds.data(), fds.size(), 5) <= 0) continue;
      for (std::size_t i = 0; i < lcms.size(); ++i) {
        if (fds[i].revents & POLLIN) lcms[i]->handle();
      }
    }
  }

  template <typename Message>
  std::vector<Message> decoded(const std::string& channel) const {
    const std::lock_guard lock(mutex_);
    std::vector<Message> out;
    for (const auto& [name, bytes] : received_) {
      if (name != channel) continue;
      Message m{};
      if (m.decode(bytes.data(), 0, static_cast<int>(bytes.size())) == static_cast<int>(bytes.size())) out.push_back(m);
    }
    return out;
  }

  lcm::LCM command_lcm_;
  lcm::LCM response_lcm_;
  lcm::LCM odometry_lcm_;
  mutable std::mutex mutex_;
  std::vector<std::pair<std::string, Bytes>> received_;
  std::atomic<bool> running_{true};
  std::thread thread_;
};

}  // namespace cerebellum::test
