#include "teleop/port_driver.hpp"

namespace cerebellum {

namespace {

// the next time on a fixed grid of periods, so that frames not aligned with it (60 Hz against
// 10 Hz) do not stretch the period; restarted from now after a gap (a pause)
double next_on_grid(double scheduled_s, double now_s) {
  const double next_s = scheduled_s + kClientHeartbeatPeriodS;
  return next_s > now_s ? next_s : now_s + kClientHeartbeatPeriodS;
}

}  // namespace

void PortDriver::send_new(const HighLevelCommand& command, double now_s) {
  current_ = command;
  current_->life_count = ++life_count_ % 128;  // the wire's life_count is a small counter too
  if (!port_.submit(*current_, now_s)) ++dropped_;
  next_heartbeat_s_ = now_s + kClientHeartbeatPeriodS;  // the grid restarts at a new command
}

void PortDriver::send_heartbeat(double now_s) {
  if (!port_.submit(*current_, now_s)) ++dropped_;
  next_heartbeat_s_ = next_on_grid(next_heartbeat_s_, now_s);
}

void PortDriver::drive(const PadState& pad, bool pressed, double now_s) {
  if (stopped_) return;
  if (pressed || now_s >= next_sample_s_) {
    const DriveStep step = mapping_.next(pad);
    next_sample_s_ = next_on_grid(next_sample_s_, now_s);
    if (step.is_new) {
      send_new(step.command, now_s);
      return;
    }
  }
  if (current_ && now_s >= next_heartbeat_s_) send_heartbeat(now_s);
}

void PortDriver::stop(double now_s) {
  if (stopped_) return;
  stopped_ = true;
  const DriveStep step = mapping_.stop();
  if (step.is_new) send_new(step.command, now_s);
}

}  // namespace cerebellum
