// A reader of every control cycle (telemetry, client interfaces, tools).
#pragma once

#include "cycle/cycle_record.hpp"

namespace cerebellum {

// sees every cycle record in the loop thread; must only copy (no I/O, no blocking) and never
// act on the robot: what it wants done goes through an input of its own (a source, a request)
class CycleObserver {
 public:
  virtual ~CycleObserver() = default;
  virtual void on_cycle(const CycleRecord& record) = 0;
};

}  // namespace cerebellum
