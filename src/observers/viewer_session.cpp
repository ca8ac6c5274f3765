#include "observers/viewer_session.hpp"

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <thread>

#include "loop/mc.hpp"
#include "viz/viewer_window.hpp"

namespace cerebellum {
namespace {

constexpr double kSlowMotionFactor = 0.25;
constexpr auto kFramePeriod = std::chrono::microseconds(16667);  // about 60 frames per second

// what the viewer asks of the loop thread
struct PaceRequest {
  bool paused = false;
  bool slow_motion = false;
  bool quit = false;
};

// the speed a run segment is paced at: slow motion of a lockstep run is 0.25x real time
double segment_speed(double base_speed, bool slow_motion) {
  if (!slow_motion) return base_speed;
  return (base_speed > 0.0 ? base_speed : 1.0) * kSlowMotionFactor;
}

std::string run_state_text(const PaceRequest& pace, double base_speed) {
  if (pace.paused) return "paused";
  const double speed = segment_speed(base_speed, pace.slow_motion);
  char text[64];
  if (speed > 0.0) {
    std::snprintf(text, sizeof text, "%.2fx real time%s", speed, pace.slow_motion ? " (slow motion)" : "");
  } else {
    std::snprintf(text, sizeof text, "lockstep, full speed");
  }
  return text;
}

}  // namespace

ViewerExchange::ViewerExchange(const Simulation& simulation)
    : capture_(simulation), staging_(capture_.sized_snapshot()), shared_(capture_.sized_snapshot()) {}

void ViewerExchange::on_cycle(const CycleRecord& record) {
  capture_.capture(record, staging_);
  if (snapshot_mutex_.try_lock()) {
    shared_ = staging_;  // same sizes: no allocation
    has_snapshot_ = true;
    snapshot_mutex_.unlock();
  }
}

bool ViewerExchange::latest(SimSnapshot& out) {
  std::lock_guard<std::mutex> lock(snapshot_mutex_);
  if (has_snapshot_) out = shared_;
  return has_snapshot_;
}

ViewerSession::ViewerSession(Mc& mc)
    : mc_(mc),
      window_(std::make_unique<ViewerWindow>(mc.simulation().model(), "cerebellum: simulated CyberDog2",
                                             keyboard_mapping_help())),
      exchange_(mc.simulation()),
      keyboard_driver_(mc.client_port(HighLevelSource::ViewerKeyboard)) {
  mc.loop().add_observer(exchange_);
}

void ViewerSession::drive_from_keys(double now_s) {
  bool focus_lost = false;
  for (const ViewerKey& key : window_->take_keys(focus_lost)) keyboard_.key(key.key_code, key.down);
  if (focus_lost) keyboard_.release_all();
  const bool pressed = keyboard_.pressed_since_sample();
  keyboard_driver_.drive(keyboard_.sample(), pressed, now_s);
}

std::string ViewerSession::keyboard_text() {
  const std::optional<HighLevelCommand> command = keyboard_driver_.current();
  if (!command) return "none pressed yet (1 stands the robot up)";
  while (const std::optional<ClientNote> note = keyboard_driver_.next_note()) {
    if (!note->clamped) {
      keyboard_refusal_ = note->reason;
      refused_life_count_ = command->life_count;
    }
  }
  if (refused_life_count_ != command->life_count) keyboard_refusal_.clear();  // a newer command since
  const ModeInfo* mode = find_mode(command->mode);
  char text[192];
  std::snprintf(text, sizeof text, "sent mode %d (%s) gait %d%s%s", command->mode,
                mode != nullptr ? mode->name : "?", command->gait_id, keyboard_refusal_.empty() ? "" : ": refused: ",
                keyboard_refusal_.c_str());
  return text;
}

ViewerSession::~ViewerSession() = default;

RunStats ViewerSession::run(const RunOptions& options, const std::atomic<bool>& stop,
                            const std::string& screenshot_png) {
  std::mutex pace_mutex;
  std::condition_variable pace_changed;
  PaceRequest pace;
  std::atomic<bool> interrupt{false};  // ends the current run segment
  std::atomic<bool> finished{false};
  RunStats total;

  // the loop thread runs paced segments; a change of pace ends the segment and starts the next
  std::thread loop_thread([&] {
    const RobotBackend& backend = mc_.backend();
    const double start_s = backend.time_s();
    const auto reached_end = [&] {
      return options.duration_s >= 0.0 && backend.time_s() - start_s >= options.duration_s - 1e-9;
    };
    while (!reached_end()) {
      double speed = 0.0;
      {
        std::unique_lock<std::mutex> lock(pace_mutex);
        pace_changed.wait(lock, [&] { return pace.quit || !pace.paused; });
        if (pace.quit) break;
        speed = segment_speed(options.speed, pace.slow_motion);
        interrupt.store(false);
      }
      const double remaining_s = options.duration_s < 0.0 ? -1.0 : options.duration_s - (backend.time_s() - start_s);
      const RunStats segment = mc_.loop().run({remaining_s, speed}, interrupt);
      total.ticks += segment.ticks;
      total.late_substeps += segment.late_substeps;
      total.pace_slips += segment.pace_slips;
      total.slipped_wall_s += segment.slipped_wall_s;
      total.wall_time_s += segment.wall_time_s;
    }
    total.robot_time_s = backend.time_s() - start_s;
    finished.store(true);
  });

  const auto set_pace = [&](const PaceRequest& request) {
    std::lock_guard<std::mutex> lock(pace_mutex);
    pace = request;
    interrupt.store(true);
    pace_changed.notify_all();
  };

  SimSnapshot snapshot;
  PaceRequest shown;
  auto next_frame = std::chrono::steady_clock::now();
  while (!finished.load()) {
    window_->poll();
    const ViewerControls& controls = window_->controls();
    if (controls.quit || stop.load()) {
      set_pace({shown.paused, shown.slow_motion, true});
      break;
    }
    if (window_->take_pace_change()) {
      shown = {controls.paused, controls.slow_motion, false};
      set_pace(shown);
    }
    mc_.simulation().request_push(window_->push());
    if (exchange_.latest(snapshot)) {
      drive_from_keys(snapshot.time_s);
      window_->draw(snapshot, run_state_text(shown, options.speed), keyboard_text());
    }
    next_frame += kFramePeriod;
    std::this_thread::sleep_until(next_frame);
    if (next_frame < std::chrono::steady_clock::now()) next_frame = std::chrono::steady_clock::now();
  }
  loop_thread.join();
  mc_.simulation().request_push({});

  if (!screenshot_png.empty()) {
    if (!exchange_.latest(snapshot)) throw std::runtime_error("viewer: no frame to save (the loop never ticked)");
    if (!window_->draw_and_save(snapshot, run_state_text(shown, options.speed), keyboard_text(), screenshot_png)) {
      throw std::runtime_error("viewer: cannot save the screenshot to " + screenshot_png);
    }
  }
  return total;
}

}  // namespace cerebellum
