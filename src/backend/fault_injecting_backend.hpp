// A RobotBackend around any other that makes it misbehave on request: motor faults as the drivers
// report them (and the driver stopping its motor), a seized or weak joint, IMU bias / freeze /
// dropout / NaN, a battery reporting less charge, faster drain, less capacity or a sagging
// voltage, a slippery foot (needs the simulation). Faults come from a timed scenario and, at run
// time, from any thread through request(); both take effect at the next read() in the loop
// thread. Without faults every call passes straight through.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "backend/fault_request.hpp"
#include "backend/robot_backend.hpp"
#include "backend/simulation.hpp"

namespace cerebellum {

// one fault at a robot time (a scenario's entry)
struct TimedFault {
  double at_s = 0.0;
  FaultRequest request;
};

class FaultInjectingBackend final : public RobotBackend {
 public:
  // simulation: the same robot's simulation handle for the physical faults (foot friction), or
  // nullptr; scenario: faults at robot times, in any order
  FaultInjectingBackend(std::unique_ptr<RobotBackend> inner, Simulation* simulation,
                        std::vector<TimedFault> scenario = {});

  SensorFrame read() override;
  void write(const JointCommand& command) override;
  void advance(double period_s) override { inner_->advance(period_s); }
  double time_s() const override { return inner_->time_s(); }

  // any thread: queue a fault (or a clear) for the next tick; "" when taken, else why not
  std::string request(const FaultRequest& request);

 private:
  struct InjectedMotorFault {
    FaultKind kind = FaultKind::Clear;
    double value = 0.0;
    double until_s = -1.0;  // < 0: until cleared
    double q = 0.0;         // the joint angle when it struck (stuck, encoder lost, disconnected)
  };
  struct ImuFault {
    FaultKind kind = FaultKind::Clear;
    double value = 0.0;
    double until_s = -1.0;
    SensorFrame frozen;  // the IMU sample when it froze
  };
  struct BatteryFault {
    bool active = false;
    double value = 0.0;
    double until_s = -1.0;
  };

  void take_requests(double now_s);
  void apply(const FaultRequest& request, double now_s);
  void expire(double now_s);
  void apply_battery(SensorFrame& frame);
  void set_slippery(int leg, bool on, double friction);

  std::unique_ptr<RobotBackend> inner_;
  Simulation* simulation_;
  std::vector<TimedFault> scenario_;  // sorted by time
  std::size_t next_scenario_ = 0;
  // run-time requests: written by any thread, taken by the loop thread
  std::mutex mailbox_mutex_;
  std::vector<FaultRequest> mailbox_;
  // the loop thread's faults
  JointArray<InjectedMotorFault> motors_{};
  ImuFault imu_;
  BatteryFault soc_, drain_, capacity_, sag_;
  std::array<double, kNumLegs> slippery_until_s_{};
  bool reported_soc_valid_ = false;
  double reported_soc_percent_ = 100.0;
  double last_read_s_ = 0.0;
  SensorFrame last_good_;  // the inner frame of the previous read
  JointArray<std::uint32_t> reported_faults_{};
};

}  // namespace cerebellum
