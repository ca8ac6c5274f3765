// The robot an MC runs on: any RobotBackend (MuJoCo, hardware, or a decorator around either) and,
// for a simulated robot, the simulation handle of the same robot that only tools and tests use.
#pragma once

#include <memory>

#include "backend/fault_injecting_backend.hpp"
#include "backend/robot_backend.hpp"
#include "backend/simulation.hpp"

namespace cerebellum {

struct McRobot {
  std::unique_ptr<RobotBackend> backend;
  Simulation* simulation = nullptr;  // nullptr on hardware; must live as long as backend
  // the fault injector the backend is (or wraps), or nullptr; must live as long as backend
  FaultInjectingBackend* faults = nullptr;
};

}  // namespace cerebellum
