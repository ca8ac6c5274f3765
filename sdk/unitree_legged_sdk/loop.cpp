#include "unitree_legged_sdk/loop.h"

#include <pthread.h>
#include <sched.h>

#include <chrono>
#include <cstdio>
#include <stdexcept>

namespace UNITREE_LEGGED_SDK {

LoopFunc::LoopFunc(std::string name, float period, const Callback& callback)
    : LoopFunc(std::move(name), period, -1, callback) {}

LoopFunc::LoopFunc(std::string name, float period, int bindCPU, const Callback& callback)
    : name_(std::move(name)), period_s_(period), cpu_(bindCPU), callback_(callback) {
  if (!(period > 0.0f)) throw std::invalid_argument("LoopFunc " + name_ + ": the period must be > 0 s");
  if (!callback_) throw std::invalid_argument("LoopFunc " + name_ + ": no callback");
}

LoopFunc::~LoopFunc() { shutdown(); }

void LoopFunc::start() {
  if (running_.exchange(true)) return;
  thread_ = std::thread([this] { run(); });
}

void LoopFunc::shutdown() {
  running_.store(false);
  if (thread_.joinable()) thread_.join();
}

void LoopFunc::run() {
  if (cpu_ >= 0) {
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(cpu_, &set);
    if (pthread_setaffinity_np(pthread_self(), sizeof set, &set) != 0) {
      std::fprintf(stderr, "LoopFunc %s: cannot pin to CPU %d, running unpinned\n", name_.c_str(), cpu_);
    }
  }
  using Clock = std::chrono::steady_clock;
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(period_s_));
  auto next = Clock::now();
  while (running_.load()) {
    callback_();
    next += period;
    const auto now = Clock::now();
    // fell behind by more than a period: start counting again from now instead of bursting
    if (now > next + period) next = now;
    std::this_thread::sleep_until(next);
  }
}

}  // namespace UNITREE_LEGGED_SDK
