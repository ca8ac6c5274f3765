#include "cli/log_replay.hpp"

#include <lcm/eventlog.h>
#include <lcm/lcm.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <thread>

#include "cli/log_options.hpp"

namespace cerebellum {
namespace {

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

struct EventlogCloser {
  void operator()(lcm_eventlog_t* log) const { lcm_eventlog_destroy(log); }
};
struct EventCloser {
  void operator()(lcm_eventlog_event_t* event) const { lcm_eventlog_free_event(event); }
};
struct LcmCloser {
  void operator()(lcm_t* lcm) const { lcm_destroy(lcm); }
};
using Eventlog = std::unique_ptr<lcm_eventlog_t, EventlogCloser>;
using Event = std::unique_ptr<lcm_eventlog_event_t, EventCloser>;
using Lcm = std::unique_ptr<lcm_t, LcmCloser>;

Eventlog open_log(const std::string& path) {
  Eventlog log(lcm_eventlog_create(path.c_str(), "r"));
  if (!log) throw std::runtime_error("cannot read the LCM log " + path);
  return log;
}

struct Source {
  Eventlog log;
  Lcm lcm;
  Event next;
};

}  // namespace

std::vector<PortLog> find_port_logs(const std::string& prefix, const std::vector<int>& ports) {
  std::vector<PortLog> logs;
  if (ends_with(prefix, ".lcmlog")) {
    const std::string stem = prefix.substr(0, prefix.size() - 7);
    const std::size_t dot = stem.rfind('.');
    const std::string port_text = dot == std::string::npos ? "" : stem.substr(dot + 1);
    const auto& known = interface_ports();
    const auto port = std::find_if(known.begin(), known.end(), [&](int p) { return std::to_string(p) == port_text; });
    if (port == known.end()) {
      throw std::invalid_argument("cannot tell the port of " + prefix +
                                  ": name it <prefix>.<port>.lcmlog with a port of " + "the interface (" +
                                  lcm_port_list() + ")");
    }
    if (access(prefix.c_str(), R_OK) != 0) throw std::invalid_argument("no such log file: " + prefix);
    logs.push_back({*port, prefix});
    return logs;
  }
  for (int port : ports) {
    const std::string path = log_file_path(prefix, port);
    if (access(path.c_str(), R_OK) == 0) logs.push_back({port, path});
  }
  if (logs.empty()) {
    throw std::invalid_argument("no log files " + prefix + ".<port>.lcmlog (ports " + lcm_port_list() + ")");
  }
  return logs;
}

std::uint64_t count_log_events(const std::string& path) {
  Eventlog log = open_log(path);
  std::uint64_t events = 0;
  while (Event event{lcm_eventlog_read_next_event(log.get())}) ++events;
  return events;
}

ReplayResult replay_port_logs(const std::vector<PortLog>& logs, double speed, int ttl, const std::atomic<bool>& stop) {
  std::vector<Source> sources;
  for (const PortLog& entry : logs) {
    Source source;
    source.log = open_log(entry.path);
    const std::string url = lcm_url(entry.port, ttl);
    source.lcm.reset(lcm_create(url.c_str()));
    if (!source.lcm) {
      throw std::runtime_error("cannot open LCM on " + url + " (a multicast route is needed: see docs/lcm-types.md)");
    }
    source.next.reset(lcm_eventlog_read_next_event(source.log.get()));
    sources.push_back(std::move(source));
  }

  using Clock = std::chrono::steady_clock;
  ReplayResult result;
  const Clock::time_point wall_start = Clock::now();
  std::int64_t first_us = -1;
  std::int64_t last_us = 0;
  while (true) {
    Source* earliest = nullptr;
    for (Source& source : sources) {
      if (source.next && (!earliest || source.next->timestamp < earliest->next->timestamp)) earliest = &source;
    }
    if (!earliest) break;
    const lcm_eventlog_event_t& event = *earliest->next;
    if (first_us < 0) first_us = event.timestamp;
    const auto due = wall_start + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>((event.timestamp - first_us) * 1e-6 / speed));
    // wait in short steps so Ctrl-C stops a replay with long gaps
    while (Clock::now() < due && !stop.load()) {
      std::this_thread::sleep_until(std::min(due, Clock::now() + std::chrono::milliseconds(50)));
    }
    if (stop.load()) {
      result.stopped = true;
      break;
    }
    lcm_publish(earliest->lcm.get(), event.channel, event.data, static_cast<unsigned>(event.datalen));
    ++result.events;
    last_us = event.timestamp;
    earliest->next.reset(lcm_eventlog_read_next_event(earliest->log.get()));
  }
  result.log_span_s = first_us < 0 ? 0.0 : (last_us - first_us) * 1e-6;
  return result;
}

}  // namespace cerebellum
