// Fills SimSnapshots from the running MC, in the loop thread (copies only).
#pragma once

#include <array>

#include "backend/simulation.hpp"
#include "cycle/cycle_record.hpp"
#include "viz/sim_snapshot.hpp"

namespace cerebellum {

class SnapshotCapture {
 public:
  explicit SnapshotCapture(const Simulation& simulation);

  // a snapshot whose state vectors are sized to the model (allocates once)
  SimSnapshot sized_snapshot() const;
  // copies the cycle, the simulator state and the MC status into a sized snapshot
  void capture(const CycleRecord& record, SimSnapshot& out) const;

 private:
  const Simulation& simulation_;
  int trunk_body_ = 0;
};

// vx, vy of a world-frame velocity in the trunk frame given by quat (w, x, y, z, body to world),
// and the yaw rate (body z of angular_velocity_body)
std::array<double, 3> planar_velocity_body(const std::array<double, 4>& quat,
                                           const std::array<double, 3>& velocity_world,
                                           const std::array<double, 3>& angular_velocity_body);

}  // namespace cerebellum
