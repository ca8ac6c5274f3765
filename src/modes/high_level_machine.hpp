// The high-level state machine: client commands in, the running mode's joint command out, and the
// status the response channel reports. It is the MC's own behaviour in the SourceArbiter; a
// low-level source may take over only from Off or PureDamper. It composes parts with one job each
// and keeps only the tick's order and the status: CommandInbox (each client's ring), the source
// stages, SourceLease (which client holds the robot), CommandQueue (the holder's sequence),
// ModeSwitcher (which mode runs, whether a command may change it), SafetyReaction (what the
// protections and the body watch call for) and ClientBook (each client's counters and refusals).
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <optional>

#include "modes/source_arbiter.hpp"
#include "modes/client_book.hpp"
#include "modes/command_inbox.hpp"
#include "modes/command_queue.hpp"
#include "modes/mode.hpp"
#include "modes/mode_switcher.hpp"
#include "modes/safety_reaction.hpp"
#include "modes/source_lease.hpp"
#include "modes/source_stage.hpp"

namespace cerebellum {

// the machine's own counters (the loop thread counts, anyone reads); each client's are its ClientCounters
struct MachineCounters {
  std::atomic<std::uint64_t> lease_handovers{0};
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
  const ClientCounters& counters(HighLevelSource source = HighLevelSource::CyberDog2Lcm) const {
    return clients_.counters(source);
  }
  const MachineCounters& machine_counters() const { return counters_; }
  // the command the running mode was entered or last updated with (loop thread)
  const HighLevelCommand& running_command() const { return modes_.running_command(); }
  // the client holding the robot (loop thread); none before the first command and after the
  // holder has been silent past the heartbeat timeout
  std::optional<HighLevelSource> holder() const { return lease_.holder(); }
  // refusals of one client's commands not yet taken by its interface's logger (the loop thread
  // pushes, one consumer thread per client pops)
  ClientNoteRing& refusals(HighLevelSource source = HighLevelSource::CyberDog2Lcm) { return clients_.refusals(source); }
  // what a client's interface thread is given (before the loop starts): its ring, its refusal
  // notes and its counters
  ClientPort port(HighLevelSource source) { return clients_.port(source, inbox_); }

 private:
  // false when the command was refused
  bool apply(const RobotState& state, const HighLevelCommand& command);
  void switch_to(Mode& mode, const RobotState& state, const HighLevelCommand& command);
  void switch_to(ModeId mode, const RobotState& state);
  // the client's sequence is dropped (a protection, a timeout, a body fault)
  void drop_sequence();
  // a refusal of a command of the client holding the robot (the queue's), or of `source`'s
  void refuse(const HighLevelCommand& command, const char* reason, const char* holder = nullptr,
              SwitchStatus status = SwitchStatus::BanTransition, std::optional<HighLevelSource> source = std::nullopt);
  // one tick of client input into the queue, counted; false when it holds no new command
  bool take_input(const TimedCommand& input);
  // the lease: true when the input's client holds the robot or may take it over now
  bool holds_lease(const TimedCommand& input);
  // the commands of this tick, from the inbox and the stages, each to take_one(const TimedCommand&)
  template <typename TakeOne>
  void take_commands(const RobotState& state, TakeOne&& take_one);
  void update_status(const RobotState& state);
  int from_mode() const;

  CommandInbox inbox_;
  std::array<SourceStage*, kHighLevelSourceCount> stages_{};
  std::size_t stage_count_ = 0;
  SourceLease lease_{CommandQueue::kHeartbeatTimeoutS};
  CommandQueue queue_;
  ModeSwitcher modes_;
  SafetyReaction safety_;
  ClientBook clients_;
  MachineCounters counters_;
  HighLevelCommand startup_;
  bool handed_over_ = false;
  std::uint64_t applied_generation_ = 0;
  HighLevelStatus status_;
  bool banned_ = false;  // the last command was refused: its status until the next accepted one
  SwitchStatus refused_status_ = SwitchStatus::BanTransition;  // BAN_TRANS, or OVER_HEAT / LOW_BAT for a flip
};

}  // namespace cerebellum
