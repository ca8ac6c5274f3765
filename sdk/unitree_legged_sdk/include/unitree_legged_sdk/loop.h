// The AlienGo SDK's periodic loop: a thread that calls a callback every `period` seconds (absolute
// deadlines, no drift), optionally pinned to one CPU.
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <thread>

namespace UNITREE_LEGGED_SDK {

// anything callable with no arguments: a lambda, std::bind, or what boost::bind returns
using Callback = std::function<void()>;

class LoopFunc {
 public:
  LoopFunc(std::string name, float period, const Callback& callback);
  // bindCPU: the CPU to pin the thread to; when pinning is impossible it warns and runs unpinned
  LoopFunc(std::string name, float period, int bindCPU, const Callback& callback);
  ~LoopFunc();
  LoopFunc(const LoopFunc&) = delete;
  LoopFunc& operator=(const LoopFunc&) = delete;

  void start();
  void shutdown();

 private:
  void run();

  std::string name_;
  double period_s_;
  int cpu_;  // -1: not pinned
  Callback callback_;
  std::atomic<bool> running_{false};
  std::thread thread_;
};

}  // namespace UNITREE_LEGGED_SDK
