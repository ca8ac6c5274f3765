// The CyberDog2 high-level interface on LCM. One thread receives robot_control_cmd (raw, decoded
// here so malformed packets are counted), stamps each command with the robot time of the newest
// cycle and hands it to the machine through its ClientPort; it hands user_gait_file texts to
// motions/ (UserGaitUpload) and answers with the result, and publishes
// robot_control_response, motor_temperature and global_to_robot from what the loop thread copies
// into a ring. The loop thread only decides what is due and copies (on_cycle).
// state_estimator and leg_control_data belong to LcmStateFeedback (io/lcm_motor_sdk), published once
// for both CyberDog2 interfaces.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "core/spsc_ring.hpp"
#include "cycle/cycle_observer.hpp"
#include "io/common/adapter_thread.hpp"
#include "io/common/count.hpp"
#include "io/common/count_report.hpp"
#include "io/common/link_faults.hpp"
#include "io/common/rate_limited_log.hpp"
#include "io/lcm_highlevel/lcm_highlevel_config.hpp"
#include "io/lcm_highlevel/response_schedule.hpp"
#include "modes/client_port.hpp"
#include "motions/user_gait_upload.hpp"

namespace lcm {
class LCM;
struct ReceiveBuffer;
}  // namespace lcm

namespace cerebellum {

struct HighLevelInterfaceCounters {
  Count commands_submitted;  // robot_control_cmd packets handed to the port
  Count wrong_fingerprint;   // robot_control_cmd packets dropped ...
  Count truncated;
  Count oversized;
  Count responses_published;
  Count odometry_published;
  Count temperatures_published;
  Count gait_files_accepted;
  Count gait_files_refused;
  Count feedback_queued;  // cycles with something due, copied by the loop thread
  Count feedback_sent;    // ... and published by the interface thread
  Count
      telemetry_dropped;  // ... and dropped: the interface thread fell behind (the ring's count, filled by counters())
};

class LcmHighLevelAdapter final : public CycleObserver {
 public:
  // opens the three urls and starts the thread; throws std::runtime_error naming a url LCM cannot
  // open. log: where notes and warnings go (never written from the loop thread)
  // port: the CyberDog2 LCM client's way into the machine; user_gaits: where received gait files
  // are checked, stored and, once both halves are valid, handed to the loop
  LcmHighLevelAdapter(ClientPort port, UserGaitUpload& user_gaits, const HighLevelLcmConfig& config,
                      double loop_period_s, std::FILE* log);
  ~LcmHighLevelAdapter() override;
  LcmHighLevelAdapter(const LcmHighLevelAdapter&) = delete;
  LcmHighLevelAdapter& operator=(const LcmHighLevelAdapter&) = delete;
  // simulation only: robot_control_cmd packets pass these link faults before they are decoded
  void attach_link_faults(LinkFaults& faults) { link_faults_.store(&faults); }

  // loop thread, right after the tick: note the robot time, decide what is due, copy
  void on_cycle(const CycleRecord& record) override;

  // stops the thread (publishing what is queued) and prints one summary line to out
  void finish(std::FILE* out);
  HighLevelInterfaceCounters counters() const;
  const UserGaitStore& user_gaits() const { return user_gaits_.store(); }

 private:
  struct Telemetry {
    PublishDue due;
    std::uint64_t tick = 0;
    HighLevelStatus status;
    RobotState state;
  };
  struct LoggedCounts {
    std::uint64_t wrong_fingerprint = 0, truncated = 0, oversized = 0;
    std::uint64_t non_finite = 0, queue_full = 0, ring_overflow = 0, wrong_thread = 0, timeouts = 0,
                  telemetry_dropped = 0;
  };

  void step();
  void drain();
  void on_command(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void handle_command(const std::uint8_t* data, std::size_t size);
  void on_gait_file(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void publish(const Telemetry& telemetry);
  void publish_response(const HighLevelStatus& status, std::uint64_t tick);
  void keep_response_alive();
  void log_refusals();
  void log_counts_once_per_second();
  LoggedCounts current_counts() const;

  ClientPort port_;
  UserGaitUpload& user_gaits_;
  std::FILE* log_;
  std::atomic<LinkFaults*> link_faults_{nullptr};
  double keepalive_s_;
  std::unique_ptr<lcm::LCM> command_lcm_;
  std::unique_ptr<lcm::LCM> response_lcm_;
  std::unique_ptr<lcm::LCM> odometry_lcm_;
  // loop thread
  ResponseSchedule schedule_;
  // loop thread -> interface thread
  SpscRing<Telemetry, 128> telemetry_;
  std::atomic<double> robot_time_s_{0.0};  // of the newest cycle: stamps received commands
  std::atomic<std::uint64_t> latest_tick_{0};
  // the interface thread counts (the loop thread: feedback_queued); anyone reads
  HighLevelInterfaceCounters counts_;
  // interface thread only
  HighLevelStatus last_status_;
  bool has_status_ = false;
  std::uint64_t last_response_tick_ = 0;
  double last_response_wall_s_ = 0.0;
  RateLimitedLog refusal_log_;
  RateLimitedLog gait_file_log_;
  LoggedCounts logged_counts_;
  EveryPeriod count_log_period_;
  // last member: started once everything above is built, stopped first
  AdapterThread thread_;
};

}  // namespace cerebellum
