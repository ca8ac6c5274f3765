// state_estimator and leg_control_data: the state feedback both CyberDog2 LCM interfaces list
// (the high-level interface at 50 Hz, the motor SDK every tick in motor mode). One publisher owns
// them, whichever of the two interfaces are enabled, so each message goes out once: every
// `feedback period` (50 Hz), and every tick while the motor SDK holds the robot. Its thread
// publishes what the loop thread copies into a ring; nothing here runs inside the tick but the copy.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

#include "core/robot_state.hpp"
#include "core/spsc_ring.hpp"
#include "core/types.hpp"
#include "cycle/cycle_observer.hpp"
#include "io/common/adapter_thread.hpp"
#include "lowlevel/motor_sdk/motor_sdk_source.hpp"

namespace lcm {
class LCM;
}  // namespace lcm

namespace cerebellum {

// 50 Hz: the rate both interface documents give outside motor mode
inline constexpr double kStateFeedbackPeriodS = 0.020;

class LcmStateFeedback final : public CycleObserver {
 public:
  // leg_control_url: leg_control_data (7667); estimator_url: state_estimator (7669). motor_sdk:
  // the motor SDK's source, whose motor mode raises the rate to every tick; nullptr when that
  // interface is off. Throws std::runtime_error naming a url LCM cannot open.
  LcmStateFeedback(const std::string& leg_control_url, const std::string& estimator_url, double loop_period_s,
                   const MotorSdkSource* motor_sdk);
  ~LcmStateFeedback() override;
  LcmStateFeedback(const LcmStateFeedback&) = delete;
  LcmStateFeedback& operator=(const LcmStateFeedback&) = delete;

  // loop thread: decides whether this tick is due and copies the state and command
  void on_cycle(const CycleRecord& record) override;

  // stops the thread after publishing what is queued
  void finish();
  std::uint64_t published() const { return published_.load(std::memory_order_relaxed); }
  std::uint64_t dropped() const { return feedback_.dropped(); }

 private:
  struct Feedback {
    RobotState state;
    JointCommand command;
  };

  void publish(const Feedback& feedback);

  std::unique_ptr<lcm::LCM> leg_control_lcm_;
  std::unique_ptr<lcm::LCM> estimator_lcm_;
  std::uint64_t ticks_per_message_;
  const MotorSdkSource* motor_sdk_;
  SpscRing<Feedback, 64> feedback_;
  std::atomic<std::uint64_t> published_{0};
  // last member: started once everything above is built, stopped first
  AdapterThread thread_;
};

}  // namespace cerebellum
