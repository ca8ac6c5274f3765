// What the shared-memory source has to say (rejected frames, take-over, refusal, timeouts), as a
// plain value: the source decides what happened on the loop thread, the edge prints it on a
// thread of its own (io/shm_lowlevel/shm_event_log.hpp).
#pragma once

#include "lowlevel/shm/shm_command_rules.hpp"

namespace cerebellum {

enum class ShmEventKind { FrameRejected, Latched, Refused, CommandTimedOut, CommandResumed };

struct ShmEvent {
  ShmEventKind kind = ShmEventKind::FrameRejected;
  double time_s = 0.0;           // robot time
  ShmCommandCheck check;         // FrameRejected
  const char* holder = nullptr;  // Refused: who has the robot (a string literal of the arbiter or a source)
  int missed_cycles = 0;         // CommandTimedOut
  double damping_kd = 0.0;       // CommandTimedOut
};

}  // namespace cerebellum
