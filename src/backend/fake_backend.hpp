// A scripted robot for unit tests: every joint is a unit inertia driven by the motor law.
#pragma once

#include <vector>

#include "backend/robot_backend.hpp"

namespace cerebellum {

class FakeBackend final : public RobotBackend {
 public:
  explicit FakeBackend(const JointArray<double>& initial_q = {});

  SensorFrame read() override;
  void write(const JointCommand& command) override;
  void advance(double period_s) override;
  double time_s() const override { return frame_.time_s; }

  // what the controller side has written, in order
  const std::vector<JointCommand>& written() const { return written_; }
  // tests may edit the sensor frame directly (IMU, temperatures, faults)
  SensorFrame& frame() { return frame_; }
  int read_count() const { return read_count_; }

 private:
  SensorFrame frame_;
  JointCommand command_{};
  std::vector<JointCommand> written_;
  int read_count_ = 0;
};

}  // namespace cerebellum
