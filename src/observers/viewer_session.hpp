// `cerebellum sim --viewer`: the live window in the main thread, the control loop in its own
// thread. The loop hands a snapshot (qpos, qvel, status) over a mutex each tick; the window posts
// pushes to the simulation, which applies them at its own steps; pause and slow motion restart
// the paced run at the new speed.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <string>

#include "loop/control_loop.hpp"
#include "observers/viewer_snapshot.hpp"
#include "backend/simulation.hpp"

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
  Mc& mc_;
  std::unique_ptr<ViewerWindow> window_;
  ViewerExchange exchange_;
};

}  // namespace cerebellum
