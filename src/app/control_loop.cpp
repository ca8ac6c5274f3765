#include "app/control_loop.hpp"

#include <chrono>
#include <stdexcept>
#include <thread>

namespace cerebellum {

ControlLoop::ControlLoop(RobotBackend& backend, StateEstimator& estimator, MotionController& controller,
                         const GuardLimits& guard_limits, double period_s)
    : backend_(backend), estimator_(estimator), controller_(controller), guard_limits_(guard_limits),
      period_s_(period_s) {
  if (!(period_s > 0.0)) throw std::invalid_argument("control period must be > 0 s");
  observers_.reserve(8);
}

void ControlLoop::add_observer(CycleObserver& observer) { observers_.push_back(&observer); }

const CycleRecord& ControlLoop::tick() {
  // read
  const SensorFrame frame = backend_.read();
  // estimate
  estimator_.update(frame, record_.state);
  // decide and control: an invalid state gets no command from the controller
  if (record_.state.valid) controller_.compute(record_.state, record_.command);
  // guard, always last
  record_.safety = guard_command(record_.state, record_.command, guard_limits_);
  // write, then the robot runs one period
  backend_.write(record_.command);
  for (CycleObserver* observer : observers_) observer->on_cycle(record_);
  backend_.advance(period_s_);
  ++record_.tick;
  return record_;
}

RunStats ControlLoop::run(const RunOptions& options, const std::atomic<bool>& stop) {
  using Clock = std::chrono::steady_clock;
  RunStats stats;
  const Clock::time_point wall_start = Clock::now();
  const double robot_start = backend_.time_s();
  const bool paced = options.speed > 0.0;
  while (!stop.load(std::memory_order_relaxed)) {
    const double elapsed = backend_.time_s() - robot_start;
    if (options.duration_s >= 0.0 && elapsed >= options.duration_s - 1e-9) break;
    if (paced) {
      const auto deadline = wall_start + std::chrono::duration_cast<Clock::duration>(
                                             std::chrono::duration<double>(elapsed / options.speed));
      if (Clock::now() > deadline + std::chrono::duration<double>(period_s_ / options.speed)) {
        ++stats.late_ticks;
      } else {
        std::this_thread::sleep_until(deadline);
      }
    }
    tick();
    ++stats.ticks;
  }
  stats.robot_time_s = backend_.time_s() - robot_start;
  stats.wall_time_s = std::chrono::duration<double>(Clock::now() - wall_start).count();
  return stats;
}

}  // namespace cerebellum
