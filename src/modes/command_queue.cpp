#include "modes/command_queue.hpp"

#include <cmath>

#include "modes/transition_table.hpp"
#include "control/locomotion/gait_table.hpp"
#include "modes/pose_control_mode.hpp"
#include "modes/qp_stand_mode.hpp"

namespace cerebellum {
namespace {

template <typename Array>
bool finite(const Array& values) {
  for (float v : values) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

bool command_is_finite(const HighLevelCommand& c) {
  return finite(c.vel_des) && finite(c.rpy_des) && finite(c.pos_des) && finite(c.acc_des) && finite(c.ctrl_point) &&
         finite(c.foot_pose) && finite(c.step_height);
}

constexpr int kMotionMode = static_cast<int>(ModeId::Motion);

}  // namespace

HighLevelCommand hold_command_after(const HighLevelCommand& last) {
  HighLevelCommand hold = last;
  hold.duration = 0;
  hold.vel_des = {};
  if (last.mode == static_cast<int>(ModeId::QpStand)) {
    // an increment of nothing: the pose stays where the last command left it (the height is
    // absolute in mode 3, the same again)
    hold.gait_id = kQpStandIncrementalGait;
    hold.rpy_des = {};
    hold.pos_des[0] = hold.pos_des[1] = 0.0f;
  } else if (last.mode == static_cast<int>(ModeId::Locomotion)) {
    hold.gait_id = resting_gait_of(last.gait_id);
  } else {
    hold.mode = static_cast<int>(ModeId::PoseControl);
    hold.gait_id = kPoseHoldGait;
  }
  // the reference's pose hold may not follow every mode (7 -> 21 is BAN_TRANS): such a mode
  // holds itself instead of reporting a refusal of a command nobody sent
  if (is_known_mode(last.mode) && is_known_mode(hold.mode) &&
      !transition_allowed(static_cast<ModeId>(last.mode), static_cast<ModeId>(hold.mode))) {
    hold = last;
    hold.duration = 0;
    hold.vel_des = {};
  }
  return hold;
}

CommandQueue::CommandQueue(double tick_period_s) : tick_period_s_(tick_period_s) {
  entries_.reserve(kCapacity + 1);
  before_last_receive_.reserve(kCapacity + 1);
}

CommandQueue::Receipt CommandQueue::receive(const HighLevelCommand& command, double time_s, bool motion_running) {
  client_seen_ = true;
  last_receive_s_ = time_s;
  if (command.life_count == last_life_count_) return Receipt::Heartbeat;
  if (!command_is_finite(command)) return Receipt::Rejected;
  last_life_count_ = command.life_count;
  if (command.mode == -1) return Receipt::Ignored;
  if (command.mode == kMotionMode && motion_running) return Receipt::Dropped;

  const long duration_ticks = std::lround(std::floor(std::max(0, command.duration) * 1e-3 / tick_period_s_ + 1e-9));
  // kept (within the reserved capacity) until the machine has accepted or refused the command
  before_last_receive_ = entries_;
  const std::uint64_t generation_before = generation_;
  if (command.duration <= 0 && command.mode != kMotionMode) {
    entries_.clear();
    entries_.push_back({command, -1});
    start_front();
    generation_of_last_receive_ = generation_;
    return Receipt::RunsNow;
  }
  // a timed entry: endless entries waiting in front of it are dropped
  const bool front_was_endless = !entries_.empty() && entries_.front().ticks_left < 0;
  std::erase_if(entries_, [](const Entry& e) { return e.ticks_left < 0; });
  if (entries_.size() >= kCapacity) return Receipt::QueueFull;
  entries_.push_back({command, duration_ticks});
  if (entries_.size() == 1 || front_was_endless) start_front();
  generation_of_last_receive_ = generation_ != generation_before ? generation_ : 0;
  return Receipt::Queued;
}

void CommandQueue::tick(bool switching, bool hold_front) {
  if (entries_.empty() || switching) return;
  Entry& front = entries_.front();
  if (front.ticks_left < 0 || (hold_front && front.ticks_left <= 1)) return;
  if (--front.ticks_left > 0) return;
  const HighLevelCommand finished = front.command;
  last_finished_ = finished;
  entries_.erase(entries_.begin());
  if (entries_.empty()) entries_.push_back({hold_command_after(finished), -1});
  start_front();
}

bool CommandQueue::timed_out(double time_s) const {
  return client_seen_ && time_s - last_receive_s_ > kHeartbeatTimeoutS;
}

void CommandQueue::withdraw_current() {
  if (entries_.empty()) return;
  if (generation_of_last_receive_ != 0 && generation_of_last_receive_ == generation_) {
    entries_ = before_last_receive_;
    generation_of_last_receive_ = 0;
    return;
  }
  entries_.erase(entries_.begin());
  if (entries_.empty()) entries_.push_back({hold_command_after(last_finished_), -1});
  start_front();
}

void CommandQueue::clear() {
  generation_of_last_receive_ = 0;
  entries_.clear();
  client_seen_ = false;
  ++generation_;
}

void CommandQueue::start_new_client() {
  clear();
  last_life_count_ = -1;
}

const HighLevelCommand* CommandQueue::current() const { return entries_.empty() ? nullptr : &entries_.front().command; }

void CommandQueue::start_front() { ++generation_; }

}  // namespace cerebellum
