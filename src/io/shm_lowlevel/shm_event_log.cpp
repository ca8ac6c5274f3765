#include "io/shm_lowlevel/shm_event_log.hpp"

#include <chrono>

#include "core/joint_layout.hpp"
#include "io/common/wall_clock.hpp"

namespace cerebellum {
namespace {

constexpr int kClientLinesPerSecond = 5;

}  // namespace

ShmEventLog::ShmEventLog(std::FILE* out)
    : out_(out),
      client_lines_(out, "cerebellum shm", "rejected command frames", kClientLinesPerSecond),
      ignored_lines_(out, "cerebellum shm", "ignored command frames", kClientLinesPerSecond) {
  printer_ = std::thread([this] {
    while (running_.load()) {
      const std::uint64_t requested = flush_requests_.load();
      drain();
      flushes_done_.store(requested);
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    drain();
  });
}

ShmEventLog::~ShmEventLog() {
  running_.store(false);
  if (printer_.joinable()) printer_.join();
}

void ShmEventLog::flush() {
  const std::uint64_t request = flush_requests_.fetch_add(1) + 1;
  while (flushes_done_.load() < request) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

void ShmEventLog::drain() {
  client_lines_.tick(wall_seconds());
  ignored_lines_.tick(wall_seconds());
  while (auto event = ring_.try_pop()) print(*event);
  const std::size_t dropped = ring_.dropped();
  if (dropped != dropped_reported_) {
    std::fprintf(out_, "cerebellum shm: %zu more events not shown (log ring full)\n", dropped - dropped_reported_);
    dropped_reported_ = dropped;
  }
  std::fflush(out_);
}

void ShmEventLog::print(const ShmEvent& event) {
  switch (event.kind) {
    case ShmEventKind::FrameRejected: {
      const ShmCommandCheck& c = event.check;
      const char* why = c.fault == ShmCommandFault::NonFinite ? "not finite" : "gain out of range";
      char line[192];
      std::snprintf(line, sizeof line, "t=%.3f s command frame rejected: %s %s %s = %g (%s); last frame kept",
                    event.time_s, kLegNames[c.joint / kJointsPerLeg], kJointNames[c.joint % kJointsPerLeg],
                    shm_command_field_name(c.field), c.value, why);
      client_lines_.line(wall_seconds(), line);
      break;
    }
    case ShmEventKind::Latched:
      std::fprintf(out_, "cerebellum shm: t=%.3f s low-level client took control of the motors\n", event.time_s);
      break;
    case ShmEventKind::Refused: {
      char line[160];
      std::snprintf(line, sizeof line, "t=%.3f s command frames ignored: %s has the robot", event.time_s,
                    event.holder != nullptr ? event.holder : "another source");
      ignored_lines_.line(wall_seconds(), line);
      break;
    }
    case ShmEventKind::CommandTimedOut:
      std::fprintf(out_,
                   "cerebellum shm: t=%.3f s no command frame for %d cycles: command cleared, motors damped "
                   "(kp 0, kd %.2f, tau 0)\n",
                   event.time_s, event.missed_cycles, event.damping_kd);
      break;
    case ShmEventKind::CommandResumed:
      std::fprintf(out_, "cerebellum shm: t=%.3f s command frames resumed\n", event.time_s);
      break;
  }
}

}  // namespace cerebellum
