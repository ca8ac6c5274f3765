// `cerebellum sim --viewer`: the live window in the main thread, the control loop in its own
// thread. The loop hands a snapshot (qpos, qvel, status) over a mutex each tick; the window posts
// pushes to the simulation, which applies them at its own steps; pause and slow motion restart
// the paced run at the new speed. The window's other keys drive the robot (teleop/keyboard_pad): the
// viewer is then a high-level client of its own (HighLevelSource::ViewerKeyboard), holding the
// robot like any other client and handing its commands through its ClientPort from this thread.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <string>

#include "loop/control_loop.hpp"
#include "observers/viewer_snapshot.hpp"
#include "backend/simulation.hpp"
#include "teleop/keyboard_pad.hpp"
#include "teleop/port_driver.hpp"

namespace cerebellum {

class Mc;
class ViewerWindow;

// the loop side: a CycleObserver that copies snapshots out (it only reads)
class ViewerExchange final : public CycleObserver {
 public:
  explicit ViewerExchange(const Simulation& simulation);

  // loop thread; never waits for the viewer (a busy snapshot is handed over next tick)
  void on_cycle(const CycleRecord& record) override;
  // viewer thread: the newest snapshot, false before the first tick
  bool latest(SimSnapshot& out);

 private:
  SnapshotCapture capture_;
  SimSnapshot staging_;  // loop thread
  std::mutex snapshot_mutex_;
  SimSnapshot shared_;
  bool has_snapshot_ = false;
};

class ViewerSession {
 public:
  // opens the window (throws std::runtime_error when there is no display) and attaches to the loop
  explicit ViewerSession(Mc& mc);
  ~ViewerSession();
  ViewerSession(const ViewerSession&) = delete;
  ViewerSession& operator=(const ViewerSession&) = delete;

  // runs until the duration is reached, the window closes or stop is set; screenshot_png: when
  // not empty, the last frame is saved there (throws std::runtime_error when that fails)
  RunStats run(const RunOptions& options, const std::atomic<bool>& stop, const std::string& screenshot_png);

 private:
  // the keys since the last frame into the keyboard's pad, and the pad to the MC at robot time now_s
  void drive_from_keys(double now_s);
  // the keyboard's command and its last refusal, for the overlay
  std::string keyboard_text();

  Mc& mc_;
  std::unique_ptr<ViewerWindow> window_;
  ViewerExchange exchange_;
  KeyboardPad keyboard_;
  PortDriver keyboard_driver_;
  std::string keyboard_refusal_;
  int refused_life_count_ = -1;
};

}  // namespace cerebellum
