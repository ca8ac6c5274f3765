// Plays LCM log files back, one file per interface port: the events of all files are merged by
// their recorded time and each is published on the port its file was recorded on, so the
// timing between ports is kept (separate lcm-logplayer processes would each start at their own
// first event).
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

namespace cerebellum {

struct PortLog {
  int port = 0;
  std::string path;
};

struct ReplayResult {
  std::uint64_t events = 0;
  double log_span_s = 0.0;  // recorded time from the first to the last event played
  bool stopped = false;     // stop was set before the end
};

// the files <prefix>.<port>.lcmlog that exist among ports, or, when prefix itself names such a
// file, just that one; throws std::invalid_argument when there is none or the port is unknown
std::vector<PortLog> find_port_logs(const std::string& prefix, const std::vector<int>& ports);

// number of complete events in an LCM log file; throws std::runtime_error when it cannot be read
std::uint64_t count_log_events(const std::string& path);

// publishes every event at speed x the recorded pace, on the interface group (lcm_url(port, ttl));
// throws std::runtime_error when a file or an LCM url cannot be opened
ReplayResult replay_port_logs(const std::vector<PortLog>& logs, double speed, int ttl, const std::atomic<bool>& stop);

}  // namespace cerebellum
