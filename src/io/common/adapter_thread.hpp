// The one thread of an interface adapter: it repeats a step (wait briefly for packets, publish
// what the loop queued, log) until stopped, then runs a last drain so nothing queued is lost.
// The loop thread never waits on it.
#pragma once

#include <atomic>
#include <functional>
#include <thread>

namespace cerebellum {

class AdapterThread {
 public:
  AdapterThread() = default;
  ~AdapterThread() { stop(); }
  AdapterThread(const AdapterThread&) = delete;
  AdapterThread& operator=(const AdapterThread&) = delete;

  // step must return within a few milliseconds (it waits for packets with a timeout)
  void start(std::function<void()> step, std::function<void()> drain = {}) {
    running_.store(true);
    thread_ = std::thread([this, step = std::move(step), drain = std::move(drain)] {
      while (running_.load()) step();
      if (drain) drain();
    });
  }
  // joins the thread; safe to call twice
  void stop() {
    running_.store(false);
    if (thread_.joinable()) thread_.join();
  }
  bool running() const { return running_.load(); }

 private:
  std::atomic<bool> running_{false};
  std::thread thread_;
};

}  // namespace cerebellum
