#include "backend/fake_backend.hpp"

#include "backend/motor_model.hpp"
#include "core/robot_model.hpp"

namespace cerebellum {

FakeBackend::FakeBackend(const JointArray<double>& initial_q) {
  frame_.q = initial_q;
  frame_.imu_accel = {0.0, 0.0, robot::kGravityMPerS2};
}

SensorFrame FakeBackend::read() {
  ++read_count_;
  return frame_;
}

void FakeBackend::write(const JointCommand& command) {
  command_ = command;
  written_.push_back(command);
}

void FakeBackend::advance(double period_s) {
  // semi-implicit Euler of q'' = tau for each joint
  const MotorLimits limits;
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    const double tau =
        limit_motor_torque(motor_law_torque(command_.q_des[i], command_.qd_des[i], command_.kp[i], command_.kd[i],
                                            command_.tau_ff[i], frame_.q[i], frame_.qd[i]),
                           frame_.qd[i], limits);
    frame_.tau[i] = tau;
    frame_.qd[i] += tau * period_s;
    frame_.q[i] += frame_.qd[i] * period_s;
  }
  frame_.time_s += period_s;
}

}  // namespace cerebellum
