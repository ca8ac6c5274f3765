// The one thread of an interface adapter: it repeats a step (wait briefly for packets, publish
// what the loop queued, log) until stopped, then runs a last drain so nothing queued is lost.
// The loop thread never waits on it.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
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
  // the thread as the publisher of a ring the loop thread fills: each step publishes everything
  // queued, or naps briefly when nothing is (a tick is 2 ms); stopping publishes what is left
  template <typename Ring, typename Publish>
  void start_publishing(Ring& ring, Publish publish) {
    start(
        [&ring, publish] {
          if (publish_queued(ring, publish) == 0) std::this_thread::sleep_for(kIdleNap);
        },
        [&ring, publish] { publish_queued(ring, publish); });
  }
  // joins the thread; safe to call twice
  void stop() {
    running_.store(false);
    if (thread_.joinable()) thread_.join();
  }
  bool running() const { return running_.load(); }

 private:
  static constexpr std::chrono::microseconds kIdleNap{500};

  template <typename Ring, typename Publish>
  static std::size_t publish_queued(Ring& ring, const Publish& publish) {
    std::size_t published = 0;
    while (auto item = ring.try_pop()) {
      publish(*item);
      ++published;
    }
    return published;
  }

  std::atomic<bool> running_{false};
  std::thread thread_;
};

}  // namespace cerebellum
