// The high-level state machine: client commands in (through CommandQueue), the running mode's
// joint command out, and the status the response channel reports. It is the MC's own behaviour
// in the SourceArbiter; a low-level source may take over only from Off or PureDamper.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <optional>

#include "modes/source_arbiter.hpp"
#include "core/spsc_ring.hpp"
#include "modes/command_inbox.hpp"
#include "modes/command_queue.hpp"
#include "modes/mode.hpp"
#include "modes/source_lease.hpp"
#include "modes/source_stage.hpp"
#include "safety/lift_detector.hpp"
#include "safety/safety_report.hpp"

namespace cerebellum {

// counters of what happened to client input (read from any thread)
struct CommandCounters {
  std::atomic<std::uint64_t> received{0};
  std::atomic<std::uint64_t> new_commands{0};
  std::atomic<std::uint64_t> rejected_non_finite{0};
  std::atomic<std::uint64_t> queue_full{0};
  std::atomic<std::uint64_t> motions_dropped{0};  // mode-62 commands while a motion ran
  std::atomic<std::uint64_t> banned_transitions{0};
  // the holder went silent past the heartbeat timeout (get-down protection), per source
  std::array<std::atomic<std::uint64_t>, kHighLevelSourceCount> timeouts{};
  // commands and heartbeats of a client refused while another one holds the robot, per source
  std::array<std::atomic<std::uint64_t>, kHighLevelSourceCount> refused_not_holder{};
  std::atomic<std::uint64_t> lease_handovers{0};
};

// why the last command was refused, for a publisher thread to log (written in the loop thread)
struct RefusalNote {
  int mode = 0;
  int gait_id = 0;
  int from_mode = 0;
  const char* reason = "";       // a static string
  const char* holder = nullptr;  // the low-level source holding the robot (static), or nullptr
};

class HighLevelMachine final : public OwnBehaviour {
 public:
  // startup: the command the MC runs by itself at start (no client, no timeout)
  HighLevelMachine(double tick_period_s, const HighLevelCommand& startup);

  // register a mode before the loop starts; the machine starts in the startup command's mode
  void add_mode(Mode& mode);
  // register a client's stage before the loop starts: its commands are taken every tick
  void add_source_stage(SourceStage& stage);

  // client thread: hand over one received command (lock-free); false when the source's ring is
  // full or another thread already submits for this source (one producer thread per source)
  bool submit(const HighLevelCommand& command, double received_s,
              HighLevelSource source = HighLevelSource::CyberDog2Lcm);
  // what happened to each source's input on its way to the tick (any thread)
  const SourceInputCounters& input_counters(HighLevelSource source) const { return inbox_.counters(source); }

  // loop thread
  void compute(const RobotState& state, JointCommand& command) override;
  // protected: the robot lies down (PureDamper), the motors go off once the guard stops them
  // (Off); client commands are refused until every cause has cleared
  void observe_health(const HealthVerdict& verdict) override;
  // the running mode's plan
  ContactPlan contact_plan() const override;
  bool allows_low_level_latch() const override;
  void on_handover() override;
  // refuses every new command (BAN_TRANS) and reports mode 15 with the live contacts and errors
  void observe_while_held(const RobotState& state, const char* holder) override;

  // the cycle record's high-level report (observers read it there)
  void report(HighLevelReport& report) const override;
  // loop thread (tests and the machine's own parts): the response fields as of the last tick
  const HighLevelStatus& status() const { return status_; }
  const CommandCounters& counters() const { return counters_; }
  // the command the running mode was entered or last updated with (loop thread)
  const HighLevelCommand& running_command() const { return running_command_; }
  // the client holding the robot (loop thread); none before the first command and after the
  // holder has been silent past the heartbeat timeout
  std::optional<HighLevelSource> holder() const { return lease_.holder(); }
  // refusals of one client's commands not yet taken by its interface's logger (the loop thread
  // pushes, one consumer thread per client pops)
  SpscRing<RefusalNote, 16>& refusals(HighLevelSource source = HighLevelSource::CyberDog2Lcm) {
    return refusals_[static_cast<std::size_t>(source)];
  }

 private:
  Mode* mode_for(int mode) const;
  // false when the command was refused
  bool apply(const RobotState& state, const HighLevelCommand& command);
  void switch_to(Mode& mode, const RobotState& state, const HighLevelCommand& command);
  // a refusal of a command of the client holding the robot (the queue's), or of `source`'s
  void refuse(const HighLevelCommand& command, const char* reason, const char* holder = nullptr,
              SwitchStatus status = SwitchStatus::BanTransition, std::optional<HighLevelSource> source = std::nullopt);
  // one tick of client input into the queue, counted; false when it holds no new command
  bool take_input(const TimedCommand& input);
  // the lease: true when the input's client holds the robot or may take it over now
  bool holds_lease(const TimedCommand& input);
  void update_status(const RobotState& state);
  // the standing modes: tipped over -> PureDamper with ori_error; picked up -> Lifted; and back
  void watch_body(const RobotState& state);
  // why a command is refused while the robot is protected or lifted, or nullptr
  const char* protection_refusal(ModeId target) const;
  // the health protection's mode: PureDamper while it damps, Off once it stopped the motors
  void protect(const RobotState& state, Protection protection);

  CommandQueue queue_;
  // the commands of this tick, from the inbox and the stages, each to take_one(const TimedCommand&)
  template <typename TakeOne>
  void take_commands(const RobotState& state, TakeOne&& take_one);

  CommandInbox inbox_;
  std::array<SourceStage*, kHighLevelSourceCount> stages_{};
  std::size_t stage_count_ = 0;
  SourceLease lease_{CommandQueue::kHeartbeatTimeoutS};
  std::array<Mode*, kMaxModeId + 1> modes_{};
  Mode* current_ = nullptr;
  HighLevelCommand startup_;
  bool started_ = false;
  bool handed_over_ = false;
  std::uint64_t applied_generation_ = 0;
  HighLevelStatus status_;
  bool banned_ = false;  // the last command was refused: its status until the next accepted one
  SwitchStatus refused_status_ = SwitchStatus::BanTransition;  // BAN_TRANS, or OVER_HEAT / LOW_BAT for a flip
  CommandCounters counters_;
  LiftDetectorConfig lift_config_;
  LiftWatch lift_watch_;              // the lift decision's memory, reset on every mode switch
  SafetyReport body_report_;          // what safety/ found wrong this tick
  HighLevelCommand running_command_;  // what the current mode was entered or last updated with
  HighLevelCommand resume_command_;   // where a lifted robot goes once set down
  bool orientation_error_ = false;    // latched until a recovery stand starts
  int foot_position_error_ = 0;       // footpos_error bits, latched likewise
  HealthVerdict health_;              // the health protection of this tick
  std::array<SpscRing<RefusalNote, 16>, kHighLevelSourceCount> refusals_;
  std::array<int, kHighLevelSourceCount> refused_life_count_{-1, -1};  // the last one noted per source
};

}  // namespace cerebellum
