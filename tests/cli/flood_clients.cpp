// Two hostile high-level clients for the liveness test: one thread publishes valid
// robot_control_cmd packets on LCM and another sends valid HighCmd datagrams to the AlienGo port,
// each as fast as it can, for a bounded time (run only inside a private network namespace:
// scripts/netns_run.sh). Prints what each sent.
//   flood_clients LCM_URL ALIENGO_PORT SECONDS
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <lcm/lcm-cpp.hpp>
#include <string>
#include <thread>

#include "io/udp_aliengo/aliengo_wire.hpp"
#include "robot_control_cmd_lcmt.hpp"

namespace {

using Clock = std::chrono::steady_clock;

std::uint64_t flood_lcm(const std::string& url, Clock::time_point end) {
  lcm::LCM lcm(url);
  if (!lcm.good()) {
    std::fprintf(stderr, "flood_clients: cannot open %s\n", url.c_str());
    return 0;
  }
  robot_control_cmd_lcmt command{};
  command.mode = 12;  // a recovery stand, repeated: a heartbeat flood of a valid command
  command.life_count = 1;
  std::uint64_t sent = 0;
  while (Clock::now() < end) {
    for (int i = 0; i < 256; ++i) sent += lcm.publish("robot_control_cmd", &command) == 0 ? 1 : 0;
  }
  return sent;
}

std::uint64_t flood_aliengo(int port, Clock::time_point end) {
  const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in target{};
  target.sin_family = AF_INET;
  target.sin_port = htons(static_cast<std::uint16_t>(port));
  target.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  cerebellum::AlienGoCommand command;
  command.mode = 1;  // force stand
  std::uint8_t frame[cerebellum::kHighCmdBytes];
  cerebellum::encode_high_cmd(command, frame);
  std::uint64_t sent = 0;
  while (Clock::now() < end) {
    for (int i = 0; i < 256; ++i) {
      const ssize_t n = ::sendto(fd, frame, sizeof frame, 0, reinterpret_cast<const sockaddr*>(&target), sizeof target);
      sent += n == static_cast<ssize_t>(sizeof frame) ? 1 : 0;
    }
  }
  ::close(fd);
  return sent;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: flood_clients LCM_URL ALIENGO_PORT SECONDS\n");
    return 2;
  }
  const std::string url = argv[1];
  const int port = std::atoi(argv[2]);
  const double seconds = std::atof(argv[3]);
  if (port <= 0 || !(seconds > 0.0 && seconds <= 60.0)) {
    std::fprintf(stderr, "flood_clients: a port > 0 and 0 < SECONDS <= 60, please\n");
    return 2;
  }
  const Clock::time_point end =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
  std::atomic<std::uint64_t> lcm_sent{0};
  std::thread lcm_thread([&] { lcm_sent = flood_lcm(url, end); });
  const std::uint64_t aliengo_sent = flood_aliengo(port, end);
  lcm_thread.join();
  std::printf("flood_clients: %llu robot_control_cmd and %llu HighCmd sent in %.1f s\n",
              static_cast<unsigned long long>(lcm_sent.load()), static_cast<unsigned long long>(aliengo_sent), seconds);
  return lcm_sent.load() > 0 && aliengo_sent > 0 ? 0 : 1;
}
