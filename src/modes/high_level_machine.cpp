#include "modes/high_level_machine.hpp"

#include <stdexcept>

#include "modes/transition_table.hpp"
#include "safety/body_watch.hpp"

namespace cerebellum {

HighLevelMachine::HighLevelMachine(double tick_period_s, const HighLevelCommand& startup)
    : queue_(tick_period_s), startup_(startup) {}

void HighLevelMachine::add_mode(Mode& mode) { modes_.add(mode); }

void HighLevelMachine::add_source_stage(SourceStage& stage) {
  if (stage_count_ == stages_.size()) throw std::logic_error("HighLevelMachine: one stage per high-level client");
  stages_[stage_count_++] = &stage;
}

template <typename TakeOne>
void HighLevelMachine::take_commands(const RobotState& state, TakeOne&& take_one) {
  // the inbox hands out at most kCommandsPerSourcePerTick per client, each stage makes at most as
  // many: a tick's input work is bounded whatever arrives. What was read before the tick comes
  // first, then what the stages make of theirs during it (a fixed order: when two clients speak
  // first at once, the lease goes the same way in every run)
  inbox_.take(take_one);
  for (std::size_t i = 0; i < stage_count_; ++i) {
    SourceStage::Commands made;
    const std::size_t count = stages_[i]->step(state, status_, made);
    for (std::size_t k = 0; k < count; ++k) take_one(made[k]);
  }
}

bool HighLevelMachine::submit(const HighLevelCommand& command, double received_s, HighLevelSource source) {
  return inbox_.push({command, received_s, source});
}

bool HighLevelMachine::allows_low_level_latch() const {
  return modes_.started() && (modes_.current_id() == ModeId::Off || modes_.current_id() == ModeId::PureDamper);
}

void HighLevelMachine::on_handover() { handed_over_ = true; }

int HighLevelMachine::from_mode() const {
  return handed_over_ ? static_cast<int>(ModeId::LowLevelMotor) : modes_.current_mode();
}

void HighLevelMachine::refuse(const HighLevelCommand& command, const char* reason, const char* holder,
                              SwitchStatus status, std::optional<HighLevelSource> source) {
  banned_ = true;
  refused_status_ = status;
  // the queue holds the commands of the client holding the robot
  const HighLevelSource of = source.value_or(lease_.holder().value_or(HighLevelSource::CyberDog2Lcm));
  clients_.refused(of, {command.mode, command.gait_id, from_mode(), reason, holder});
}

bool HighLevelMachine::holds_lease(const TimedCommand& input) {
  switch (lease_.judge(input.source, input.received_s)) {
    case SourceLease::Verdict::Holds: return true;
    case SourceLease::Verdict::TakesOver:
      // the last holder went silent (its timeout has damped the robot or will): a new client
      counters_.lease_handovers.fetch_add(1, std::memory_order_relaxed);
      queue_.start_new_client();
      applied_generation_ = queue_.generation();
      return true;
    case SourceLease::Verdict::Refused: break;
  }
  clients_.refused_not_holder(input.source, input.command, modes_.current_mode(), *lease_.holder());
  // the LCM client sees its refusal in robot_control_response
  if (input.source == HighLevelSource::CyberDog2Lcm) {
    banned_ = true;
    refused_status_ = SwitchStatus::BanTransition;
  }
  return false;
}

bool HighLevelMachine::take_input(const TimedCommand& input) {
  ClientCounters& counters = clients_.counters(input.source);
  counters.received.fetch_add(1, std::memory_order_relaxed);
  const bool motion_running =
      modes_.started() && modes_.current_id() == ModeId::Motion && modes_.current().holds_entry();
  switch (queue_.receive(input.command, input.received_s, motion_running)) {
    case CommandQueue::Receipt::RunsNow:
    case CommandQueue::Receipt::Queued: counters.new_commands.fetch_add(1, std::memory_order_relaxed); return true;
    case CommandQueue::Receipt::Rejected: counters.rejected_non_finite.fetch_add(1, std::memory_order_relaxed); break;
    case CommandQueue::Receipt::QueueFull:
      // the client sees it in the response (BAN_TRANS) and its interface's log, not only in a count
      counters.queue_full.fetch_add(1, std::memory_order_relaxed);
      refuse(input.command, "the command queue is full (timed entries waiting): the command is dropped", nullptr,
             SwitchStatus::BanTransition, input.source);
      break;
    case CommandQueue::Receipt::Dropped: clients_.motion_dropped(input.source, input.command); break;
    case CommandQueue::Receipt::Heartbeat:
    case CommandQueue::Receipt::Ignored: break;
  }
  return false;
}

void HighLevelMachine::observe_while_held(const RobotState& state, const char* holder) {
  // the latch lasts until restart: a new command is refused and never queued; heartbeats only
  // refresh the client's life_count memory
  take_commands(state, [&](const TimedCommand& input) {
    if (!take_input(input)) return;
    refuse(input.command, "a low-level client holds the robot until restart", holder, SwitchStatus::BanTransition,
           input.source);
    queue_.clear();
  });
  applied_generation_ = queue_.generation();
  update_status(state);
}

void HighLevelMachine::switch_to(Mode& mode, const RobotState& state, const HighLevelCommand& command) {
  banned_ = false;
  safety_.on_switch(mode.id());
  modes_.switch_to(mode, state, command);
}

void HighLevelMachine::switch_to(ModeId mode, const RobotState& state) {
  Mode* target = modes_.find(mode);
  if (target == nullptr) return;
  HighLevelCommand command;
  command.mode = static_cast<int>(mode);
  switch_to(*target, state, command);
}

void HighLevelMachine::drop_sequence() {
  queue_.clear();
  applied_generation_ = queue_.generation();
}

void HighLevelMachine::observe_health(const HealthVerdict& verdict) {
  // acted on in compute(); a protection lasts 0.5 s past its cause, so one that began while the
  // state could not be trusted (compute() is not called then) is still on when it can be again
  safety_.observe_health(verdict);
  // reported at once, also while compute() is not called
  if (const std::optional<SwitchStatus> status = safety_.health_status()) status_.switch_status = *status;
}

bool HighLevelMachine::apply(const RobotState& state, const HighLevelCommand& command) {
  Mode* target = modes_.find(command.mode);
  if (target == nullptr) {
    refuse(command, is_known_mode(command.mode) ? "mode not available in this MC" : "unknown mode");
    return false;
  }
  if (const char* reason = ModeSwitcher::command_refusal(*target, command)) {
    refuse(command, reason);
    return false;
  }
  if (const char* reason = safety_.refusal(target->id(), modes_.current_id())) {
    refuse(command, reason);
    return false;
  }
  if (const StartRefusal refusal = modes_.switch_refusal(*target, state, command)) {
    refuse(command, refusal.reason, nullptr, refusal.status);
    return false;
  }
  if (target == &modes_.current()) {
    banned_ = false;
    modes_.update(state, command);
  } else {
    switch_to(*target, state, command);
  }
  // the queue holds the commands of the client holding the robot
  if (const char* clamp = target->clamp_note()) {
    clients_.clamped(lease_.holder().value_or(HighLevelSource::CyberDog2Lcm), command, clamp);
  }
  return true;
}

void HighLevelMachine::compute(const RobotState& state, JointCommand& command) {
  if (!modes_.started()) {
    Mode* startup = modes_.find(startup_.mode);
    if (startup == nullptr) startup = modes_.find(ModeId::Off);
    switch_to(*startup, state, startup_);
  }
  // the health protection first: the client's sequence is dropped, and what the client sends from
  // now on meets the protected mode (and is refused in apply())
  if (safety_.health().protecting()) {
    drop_sequence();
    if (const std::optional<ModeId> target = safety_.health_target(modes_.current_id())) switch_to(*target, state);
  }
  // client input of this tick (a bounded share of each source), from the client holding the robot
  take_commands(state, [&](const TimedCommand& input) {
    if (holds_lease(input)) take_input(input);
  });
  // a client that went silent: get-down protection; a jump in the air lands first (damping a
  // robot in flight would drop it), the protection follows once it stands
  if (queue_.timed_out(state.time_s) && !modes_.current().must_finish()) {
    if (const std::optional<HighLevelSource> holder = lease_.holder()) {
      clients_.counters(*holder).timeouts.fetch_add(1, std::memory_order_relaxed);
    }
    drop_sequence();
    if (modes_.current_id() != ModeId::Off) switch_to(ModeId::PureDamper, state);
  }
  // a refused entry leaves the queue as if it had never been sent (it neither waits out its
  // duration nor leaves a hold behind); what follows it is applied at once
  for (std::size_t attempt = 0; queue_.generation() != applied_generation_; ++attempt) {
    applied_generation_ = queue_.generation();
    const HighLevelCommand* next = queue_.current();
    if (next == nullptr || apply(state, *next)) break;
    queue_.withdraw_current();
    // every withdrawal removes an entry; a hold that is refused too is not tried again
    if (attempt > CommandQueue::kCapacity) {
      applied_generation_ = queue_.generation();
      break;
    }
  }
  // the standing modes: tipped over -> PureDamper with ori_error; picked up -> Lifted; and back
  const BodyReaction reaction = safety_.watch_body(state, modes_);
  if (reaction.action == BodyReaction::Action::Damp) drop_sequence();
  if (reaction.action != BodyReaction::Action::None) {
    switch_to(*modes_.find(reaction.command.mode), state, reaction.command);
  }
  // a motion's entry lasts at least as long as the motion; the time of other entries starts once
  // their mode has finished switching
  Mode& current = modes_.current();
  const bool holds_entry = current.holds_entry();
  queue_.tick(!holds_entry && current.progress_percent() < 100, holds_entry);
  current.run(state, command);
  update_status(state);
}

void HighLevelMachine::report(HighLevelReport& report) const {
  report.status = status_;
  report.running_command = modes_.running_command();
  report.holder = lease_.holder();
  for (std::size_t i = 0; i < stage_count_; ++i) stages_[i]->report(report);
}

ContactPlan HighLevelMachine::contact_plan() const {
  return modes_.started() ? modes_.current().contact_plan() : std::nullopt;
}

void HighLevelMachine::update_status(const RobotState& state) {
  status_.contact = 0;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    if (state.contact[leg] > 0.5) status_.contact |= 1 << leg;
  }
  status_.motor_faults = state.motor_faults;
  status_.driver_mode = state.driver_mode;
  if (handed_over_) {
    // the MC commands nothing: no gait, no progress, no protective stop of its own; the body's
    // orientation is still watched so that a client sees a robot upside down
    const std::optional<SwitchStatus> health = safety_.health_status();
    status_.mode = static_cast<int>(ModeId::LowLevelMotor);
    status_.gait_id = 0;
    status_.order_process_bar = 100;
    status_.ori_error = orientation_error(state) ? 1 : 0;
    status_.footpos_error = 0;
    status_.switch_status = health ? *health : banned_ ? refused_status_ : SwitchStatus::Done;
    return;
  }
  const Mode& current = modes_.current();
  const std::optional<SwitchStatus> protection = safety_.protection_status();
  status_.mode = static_cast<int>(current.id());
  status_.gait_id = current.gait_id();
  status_.order_process_bar = current.progress_percent();
  status_.ori_error = safety_.orientation_error() ? 1 : 0;
  status_.footpos_error = safety_.foot_position_error();
  status_.switch_status = protection                        ? *protection
                          : current.damping_protection()    ? SwitchStatus::HighDamping
                          : banned_                         ? refused_status_
                          : current.id() == ModeId::Lifted  ? SwitchStatus::Lifted
                          : status_.order_process_bar < 100 ? SwitchStatus::Transitioning
                                                            : SwitchStatus::Done;
}

}  // namespace cerebellum
