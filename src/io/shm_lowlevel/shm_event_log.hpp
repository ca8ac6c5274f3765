// What the shared-memory source has to say (rejected frames, take-over, refusal, timeouts;
// lowlevel/shm/shm_event.hpp), printed by its own thread: the loop thread only copies an event
// into a ring.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <thread>

#include "core/spsc_ring.hpp"
#include "io/common/rate_limited_log.hpp"
#include "lowlevel/shm/shm_event.hpp"

namespace cerebellum {

class ShmEventLog {
 public:
  explicit ShmEventLog(std::FILE* out);
  ~ShmEventLog();
  ShmEventLog(const ShmEventLog&) = delete;
  ShmEventLog& operator=(const ShmEventLog&) = delete;

  // loop thread: never blocks; an event that does not fit is dropped and counted
  void post(const ShmEvent& event) { ring_.try_push(event); }
  // print what is queued now and wait until it is written (any thread but the loop's)
  void flush();
  // lines a client provoked that the rate limit did not print: rejected frames, and frames ignored
  // because another source has the robot (each kind has its own budget, so a client whose frames
  // are rejected still learns, once a second at least, that another source has the robot)
  std::uint64_t client_lines_suppressed() const { return client_lines_.suppressed() + ignored_lines_.suppressed(); }
  std::uint64_t ignored_lines_written() const { return ignored_lines_.written(); }

 private:
  void drain();
  void print(const ShmEvent& event);

  std::FILE* out_;
  // a client can send a bad frame every millisecond: at most a few such lines per second
  RateLimitedLog client_lines_;
  RateLimitedLog ignored_lines_;
  SpscRing<ShmEvent, 64> ring_;
  std::size_t dropped_reported_ = 0;
  std::atomic<bool> running_{true};
  std::atomic<std::uint64_t> flush_requests_{0};
  std::atomic<std::uint64_t> flushes_done_{0};
  std::thread printer_;
};

}  // namespace cerebellum
