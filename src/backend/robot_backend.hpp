// The one interface between the MC and a robot: simulated or real.
#pragma once

#include "core/robot_readings.hpp"
#include "core/types.hpp"

namespace cerebellum {

class RobotBackend {
 public:
  virtual ~RobotBackend() = default;

  // latest sensor readings
  virtual SensorFrame read() = 0;
  // the command the motor drivers execute until the next write
  virtual void write(const JointCommand& command) = 0;
  // let the robot run for one control period with the written command: a simulation integrates
  // its physics, a hardware backend returns at once (real time passes by itself)
  virtual void advance(double period_s) = 0;
  virtual double time_s() const = 0;
  // a real robot's link as of the last read (a simulation has none)
  virtual RobotLinkReport link_report() const { return {}; }
};

}  // namespace cerebellum
