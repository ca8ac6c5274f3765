// Prints the trunk height and joint state once per second of robot time, from its own thread:
// the loop thread only copies a record into a ring.
#pragma once

#include <atomic>
#include <cstdio>
#include <thread>

#include "loop/control_loop.hpp"
#include "core/spsc_ring.hpp"

namespace cerebellum {

class ConsoleReporter final : public CycleObserver {
 public:
  explicit ConsoleReporter(std::FILE* out, double interval_s = 1.0);
  ~ConsoleReporter() override;
  ConsoleReporter(const ConsoleReporter&) = delete;
  ConsoleReporter& operator=(const ConsoleReporter&) = delete;

  void on_cycle(const CycleRecord& record) override;
  // print what is still queued and stop the thread
  void finish();

 private:
  void drain();
  void print(const CycleRecord& record);

  std::FILE* out_;
  double interval_s_;
  double next_print_s_ = 0.0;  // loop thread only
  SpscRing<CycleRecord, 64> ring_;
  std::atomic<bool> running_{true};
  std::thread printer_;
};

}  // namespace cerebellum
