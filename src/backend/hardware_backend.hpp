// A real robot behind the MC (`cerebellum run`): a RobotBackend paced by the wall clock that must
// first be brought to take the MC's commands (the CyberDog2's motor mode, the ZsiBot's daemon
// answering) and says at the end what its link went through.
#pragma once

#include <atomic>
#include <cstdio>
#include <string>

#include "backend/robot_backend.hpp"

namespace cerebellum {

class HardwareBackend : public RobotBackend {
 public:
  // before the loop, on the loop's thread: until the robot takes the MC's commands; false when
  // the backend's activation timeout passes or stop is set
  virtual bool activate(const std::atomic<bool>& stop) = 0;
  // for the start: "the CyberDog2's motor mode on udpm://... (all-zero frames, up to 20 s)"
  virtual std::string activation_text() const = 0;
  // why activate() gave up, in a sentence a person can act on
  virtual std::string activation_failure() const = 0;
  // for the ready line: "CyberDog2 through its motor SDK (udpm://...)"
  virtual std::string description() const = 0;
  // stops the backend's thread and prints its summary line
  virtual void finish(std::FILE* out) = 0;
};

}  // namespace cerebellum
