// The motor SDK on LCM: one thread receives motor_ctrl (raw, decoded here so malformed packets
// are counted), stamps each frame with robot time and hands it to the MotorSdkSource; the same
// thread publishes spi_data and motor_ctrl_state (in motor mode) from the cycle records the loop
// thread copies into a ring. Nothing here runs inside the tick but the copy. state_estimator and
// leg_control_data come from LcmStateFeedback, shared with the high-level interface.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "core/spsc_ring.hpp"
#include "cycle/cycle_observer.hpp"
#include "io/common/adapter_thread.hpp"
#include "io/common/count_report.hpp"
#include "io/common/link_faults.hpp"
#include "io/lcm_motor_sdk/lcm_motor_sdk_config.hpp"
#include "lowlevel/motor_sdk/motor_sdk_source.hpp"

namespace lcm {
class LCM;
struct ReceiveBuffer;
}  // namespace lcm

namespace cerebellum {

// motor_ctrl packets that never became a frame
struct MotorCtrlRejections {
  std::uint64_t wrong_fingerprint = 0;
  std::uint64_t truncated = 0;
  std::uint64_t oversized = 0;
  std::uint64_t non_finite = 0;
};

class LcmMotorSdkAdapter final : public CycleObserver {
 public:
  // opens the control url and starts the thread; throws std::runtime_error naming a url LCM cannot
  // open. log: where warnings go (never written from the loop thread)
  LcmMotorSdkAdapter(const MotorSdkConfig& config, std::FILE* log);
  ~LcmMotorSdkAdapter() override;
  LcmMotorSdkAdapter(const LcmMotorSdkAdapter&) = delete;
  // simulation only: motor_ctrl packets pass these link faults before they are decoded
  void attach_link_faults(LinkFaults& faults) { link_faults_.store(&faults); }
  LcmMotorSdkAdapter& operator=(const LcmMotorSdkAdapter&) = delete;

  // register with SourceArbiter::add_low_level_source
  MotorSdkSource& source() { return source_; }
  // loop thread: copies the record and the source's status, nothing else
  void on_cycle(const CycleRecord& record) override;

  // stops the thread (publishing what is queued) and prints one summary line to out
  void finish(std::FILE* out);
  MotorCtrlRejections rejections() const;
  std::uint64_t telemetry_dropped() const { return telemetry_.dropped(); }

 private:
  struct Telemetry {
    CycleRecord record;
    MotorSdkStatus status;
  };
  struct Counts {
    MotorSdkCounters source;
    MotorCtrlRejections rejected;
  };

  void step();
  void drain();
  void on_motor_ctrl(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void handle_motor_ctrl(const std::uint8_t* data, std::size_t size);
  void publish(const Telemetry& telemetry);
  void log_changes(const MotorSdkStatus& status);
  void log_counts_once_per_second();

  MotorSdkSource source_;
  std::FILE* log_;
  std::atomic<LinkFaults*> link_faults_{nullptr};
  std::unique_ptr<lcm::LCM> control_lcm_;
  SpscRing<Telemetry, 64> telemetry_;
  std::atomic<double> robot_time_s_{0.0};  // of the newest cycle record, stamps received frames
  std::atomic<std::uint64_t> wrong_fingerprint_{0};
  std::atomic<std::uint64_t> truncated_{0};
  std::atomic<std::uint64_t> oversized_{0};
  // adapter thread only
  MotorSdkStatus last_status_;
  bool refusal_logged_ = false;
  Counts logged_counts_;
  EveryPeriod count_log_period_;
  // last member: started once everything above is built, stopped first
  AdapterThread thread_;
};

}  // namespace cerebellum
