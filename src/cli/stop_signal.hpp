// SIGINT / SIGTERM turned into a stop flag, without a signal handler or a global: the signals are
// blocked in every thread and a watcher thread waits for them with sigwait.
#pragma once

#include <atomic>
#include <thread>

namespace cerebellum {

class StopSignal {
 public:
  // call before starting any other thread, so every thread inherits the blocked mask
  StopSignal();
  ~StopSignal();
  StopSignal(const StopSignal&) = delete;
  StopSignal& operator=(const StopSignal&) = delete;

  const std::atomic<bool>& flag() const { return stop_; }

 private:
  std::atomic<bool> stop_{false};
  std::atomic<bool> watcher_done_{false};
  std::thread watcher_;
};

}  // namespace cerebellum
