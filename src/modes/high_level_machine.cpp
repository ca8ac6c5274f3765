#include "modes/high_level_machine.hpp"

#include <stdexcept>

#include "modes/transition_table.hpp"
#include "modes/watched_modes.hpp"
#include "safety/body_watch.hpp"

namespace cerebellum {
namespace {

// what the response says while the health protection acts: EDAMP while it damps, ESTOP once the
// motors are off; nothing without a protection
std::optional<SwitchStatus> protection_status(const HealthVerdict& verdict) {
  if (verdict.protection == Protection::Stopped) return SwitchStatus::EmergencyStop;
  if (verdict.protecting()) return SwitchStatus::HighDamping;
  return std::nullopt;
}

}  // namespace

HighLevelMachine::HighLevelMachine(double tick_period_s, const HighLevelCommand& startup)
    : queue_(tick_period_s), startup_(startup) {}

void HighLevelMachine::add_mode(Mode& mode) { modes_[static_cast<std::size_t>(mode.id())] = &mode; }

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

Mode* HighLevelMachine::mode_for(int mode) const {
  if (mode < 0 || mode >= static_cast<int>(modes_.size())) return nullptr;
  return modes_[static_cast<std::size_t>(mode)];
}

bool HighLevelMachine::allows_low_level_latch() const {
  return current_ != nullptr && (current_->id() == ModeId::Off || current_->id() == ModeId::PureDamper);
}

void HighLevelMachine::on_handover() { handed_over_ = true; }

void HighLevelMachine::refuse(const HighLevelCommand& command, const char* reason, const char* holder,
                              SwitchStatus status, std::optional<HighLevelSource> source) {
  banned_ = true;
  refused_status_ = status;
  counters_.banned_transitions.fetch_add(1, std::memory_order_relaxed);
  const int from_mode = handed_over_          ? static_cast<int>(ModeId::LowLevelMotor)
                        : current_ != nullptr ? static_cast<int>(current_->id())
                                              : -1;
  // the queue holds the commands of the client holding the robot
  const HighLevelSource of = source.value_or(lease_.holder().value_or(HighLevelSource::CyberDog2Lcm));
  refusals(of).try_push({command.mode, command.gait_id, from_mode, reason, holder});
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
  const auto source = static_cast<std::size_t>(input.source);
  counters_.refused_not_holder[source].fetch_add(1, std::memory_order_relaxed);
  // one note per new command of the refused client (heartbeats and streams repeat it)
  if (refused_life_count_[source] != input.command.life_count) {
    refused_life_count_[source] = input.command.life_count;
    refusals(input.source)
        .try_push(
            {input.command.mode, input.command.gait_id, current_ != nullptr ? static_cast<int>(current_->id()) : -1,
             input.source == HighLevelSource::CyberDog2Lcm ? "another high-level client holds the robot"
                                                           : "another high-level client holds the robot (HighCmd)",
             source_name(*lease_.holder())});
  }
  // the LCM client sees its refusal in robot_control_response
  if (input.source == HighLevelSource::CyberDog2Lcm) {
    banned_ = true;
    refused_status_ = SwitchStatus::BanTransition;
  }
  return false;
}

bool HighLevelMachine::take_input(const TimedCommand& input) {
  counters_.received.fetch_add(1, std::memory_order_relaxed);
  const bool motion_running = current_ != nullptr && current_->id() == ModeId::Motion && current_->holds_entry();
  switch (queue_.receive(input.command, input.received_s, motion_running)) {
    case CommandQueue::Receipt::RunsNow:
    case CommandQueue::Receipt::Queued: counters_.new_commands.fetch_add(1, std::memory_order_relaxed); return true;
    case CommandQueue::Receipt::Rejected: counters_.rejected_non_finite.fetch_add(1, std::memory_order_relaxed); break;
    case CommandQueue::Receipt::QueueFull: counters_.queue_full.fetch_add(1, std::memory_order_relaxed); break;
    case CommandQueue::Receipt::Dropped:
      counters_.motions_dropped.fetch_add(1, std::memory_order_relaxed);
      refusals(input.source)
          .try_push({input.command.mode, input.command.gait_id, static_cast<int>(ModeId::Motion),
                     "a motion is running: mode-62 commands are dropped until it ends", nullptr});
      break;
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
  if (current_ != nullptr && current_ != &mode) current_->exit();
  current_ = &mode;
  banned_ = false;
  running_command_ = command;
  lift_watch_ = LiftWatch{};
  if (mode.id() == ModeId::RecoveryStand) {
    orientation_error_ = false;
    foot_position_error_ = 0;
  }
  mode.enter(state, command);
}

void HighLevelMachine::observe_health(const HealthVerdict& verdict) {
  // acted on in compute(); a protection lasts 0.5 s past its cause, so one that began while the
  // state could not be trusted (compute() is not called then) is still on when it can be again
  health_ = verdict;
  // reported at once, also while compute() is not called
  if (const std::optional<SwitchStatus> status = protection_status(verdict)) status_.switch_status = *status;
}

void HighLevelMachine::protect(const RobotState& state, Protection protection) {
  // the client's sequence is dropped; what arrives while protected is refused in apply()
  queue_.clear();
  applied_generation_ = queue_.generation();
  const ModeId target = protection == Protection::Stopped ? ModeId::Off : ModeId::PureDamper;
  if (current_->id() == target || (target == ModeId::PureDamper && current_->id() == ModeId::Off)) return;
  Mode* mode = mode_for(static_cast<int>(target));
  if (mode == nullptr) return;
  HighLevelCommand command;
  command.mode = static_cast<int>(target);
  switch_to(*mode, state, command);
}

const char* HighLevelMachine::protection_refusal(ModeId target) const {
  if (health_.protecting()) {
    if (health_.causes & (kHealthMotorError | kHealthMotorWarning)) {
      return "motor error or warning: commands are ignored until it clears";
    }
    if (health_.causes & (kHealthBatteryCritical | kHealthBatteryReading)) {
      return "battery critically low: commands are ignored until it is charged";
    }
    return "sensor fault (IMU or state estimate): commands are ignored until it clears";
  }
  const bool protected_stop = orientation_error_ || foot_position_error_ != 0;
  if (protected_stop && target != ModeId::RecoveryStand && target != ModeId::Off && target != ModeId::PureDamper) {
    return orientation_error_ ? "orientation error: only a recovery stand clears it"
                              : "foot position error: only a recovery stand clears it";
  }
  if (current_->id() == ModeId::Lifted && (target == ModeId::QpStand || target == ModeId::Locomotion)) {
    return "lifted: the stand resumes by itself once the robot is set down";
  }
  return nullptr;
}

void HighLevelMachine::watch_body(const RobotState& state) {
  const ModeId id = current_->id();
  body_report_ = SafetyReport{};
  if (id == ModeId::Lifted) {
    Mode* resume = mode_for(resume_command_.mode);
    body_report_.landed = detect_landed(state, lift_watch_, lift_config_);
    if (body_report_.landed && resume != nullptr) switch_to(*resume, state, resume_command_);
    return;
  }
  if (!watches_body(id)) return;
  Mode* damper = mode_for(static_cast<int>(ModeId::PureDamper));
  body_report_ = check_body(state, watches_feet(id));
  if (body_report_.body_fault() && damper != nullptr) {
    // tipped over or a foot out of reach: damp the joints, drop the client's sequence, wait for
    // a recovery stand
    orientation_error_ = body_report_.orientation_error;
    foot_position_error_ = body_report_.footpos_error;
    queue_.clear();
    applied_generation_ = queue_.generation();
    HighLevelCommand damp;
    damp.mode = static_cast<int>(ModeId::PureDamper);
    switch_to(*damper, state, damp);
    return;
  }
  Mode* lifted = mode_for(static_cast<int>(ModeId::Lifted));
  // a jump leaves the ground on purpose: its watch starts afresh once it stands again
  if (current_->airborne()) {
    lift_watch_ = LiftWatch{};
  } else if (lifted != nullptr) {
    body_report_.lifted = detect_lifted(state, lift_watch_, lift_config_);
  }
  if (body_report_.lifted) {
    resume_command_ = command_after_landing(running_command_);
    HighLevelCommand lift;
    lift.mode = static_cast<int>(ModeId::Lifted);
    switch_to(*lifted, state, lift);
  }
}

bool HighLevelMachine::apply(const RobotState& state, const HighLevelCommand& command) {
  Mode* target = mode_for(command.mode);
  if (target == nullptr) {
    refuse(command, is_known_mode(command.mode) ? "mode not available in this MC" : "unknown mode");
    return false;
  }
  if (const char* reason = target->check(command)) {
    refuse(command, reason);
    return false;
  }
  if (const char* reason = protection_refusal(target->id())) {
    refuse(command, reason);
    return false;
  }
  if (target != current_ && !transition_allowed(current_->id(), target->id())) {
    refuse(command, "transition not allowed from the current mode");
    return false;
  }
  if (target != current_ && current_->must_finish() && target->id() != ModeId::PureDamper &&
      target->id() != ModeId::Off) {
    refuse(command, "the robot is not back on its feet yet (damping and off still stop it)");
    return false;
  }
  if (const StartRefusal refusal = target->start_refusal(state, command)) {
    refuse(command, refusal.reason, nullptr, refusal.status);
    return false;
  }
  if (target == current_) {
    banned_ = false;
    running_command_ = command;
    current_->update(state, command);
    return true;
  }
  switch_to(*target, state, command);
  return true;
}

void HighLevelMachine::compute(const RobotState& state, JointCommand& command) {
  if (!started_) {
    started_ = true;
    Mode* startup = mode_for(startup_.mode);
    if (startup == nullptr) startup = mode_for(static_cast<int>(ModeId::Off));
    switch_to(*startup, state, startup_);
  }
  // the health protection first: what the client sends from now on meets the protected mode
  if (health_.protecting()) protect(state, health_.protection);
  // client input of this tick (a bounded share of each source), from the client holding the robot
  take_commands(state, [&](const TimedCommand& input) {
    if (holds_lease(input)) take_input(input);
  });
  // a client that went silent: get-down protection; a jump in the air lands first (damping a
  // robot in flight would drop it), the protection follows once it stands
  if (queue_.timed_out(state.time_s) && !current_->must_finish()) {
    if (const std::optional<HighLevelSource> holder = lease_.holder()) {
      counters_.timeouts[static_cast<std::size_t>(*holder)].fetch_add(1, std::memory_order_relaxed);
    }
    queue_.clear();
    applied_generation_ = queue_.generation();
    Mode* damper = mode_for(static_cast<int>(ModeId::PureDamper));
    if (current_->id() != ModeId::Off && damper != nullptr) {
      HighLevelCommand damp;
      damp.mode = static_cast<int>(ModeId::PureDamper);
      switch_to(*damper, state, damp);
    }
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
  watch_body(state);
  // a motion's entry lasts at least as long as the motion; the time of other entries starts once
  // their mode has finished switching
  const bool holds_entry = current_->holds_entry();
  queue_.tick(!holds_entry && current_->progress_percent() < 100, holds_entry);
  current_->run(state, command);
  update_status(state);
}

void HighLevelMachine::report(HighLevelReport& report) const {
  report.status = status_;
  report.running_command = running_command_;
  report.holder = lease_.holder();
  for (std::size_t i = 0; i < stage_count_; ++i) stages_[i]->report(report);
}

ContactPlan HighLevelMachine::contact_plan() const {
  return current_ != nullptr ? current_->contact_plan() : std::nullopt;
}

void HighLevelMachine::update_status(const RobotState& state) {
  status_.contact = 0;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    if (state.contact[leg] > 0.5) status_.contact |= 1 << leg;
  }
  status_.motor_faults = state.motor_faults;
  const std::optional<SwitchStatus> protection = protection_status(health_);
  if (handed_over_) {
    // the MC commands nothing: no gait, no progress, no protective stop of its own; the body's
    // orientation is still watched so that a client sees a robot upside down
    status_.mode = static_cast<int>(ModeId::LowLevelMotor);
    status_.gait_id = 0;
    status_.order_process_bar = 100;
    status_.ori_error = orientation_error(state) ? 1 : 0;
    status_.footpos_error = 0;
    status_.switch_status = protection ? *protection : banned_ ? refused_status_ : SwitchStatus::Done;
    return;
  }
  status_.mode = static_cast<int>(current_->id());
  status_.gait_id = current_->gait_id();
  status_.order_process_bar = current_->progress_percent();
  status_.ori_error = orientation_error_ ? 1 : 0;
  status_.footpos_error = foot_position_error_;
  status_.switch_status = protection                         ? *protection
                          : orientation_error_               ? SwitchStatus::EmergencyStop
                          : foot_position_error_ != 0        ? SwitchStatus::HighDamping
                          : current_->damping_protection()   ? SwitchStatus::HighDamping
                          : banned_                          ? refused_status_
                          : current_->id() == ModeId::Lifted ? SwitchStatus::Lifted
                          : status_.order_process_bar < 100  ? SwitchStatus::Transitioning
                                                             : SwitchStatus::Done;
}

}  // namespace cerebellum
