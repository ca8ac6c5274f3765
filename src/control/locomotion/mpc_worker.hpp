// Runs the convex MPC in its own thread. The loop posts an input at one tick and takes the
// solution at a later tick; take() waits for a posted solve to finish, so the solution is used
// at a fixed tick and lockstep runs stay deterministic while the solve overlaps the rest of the
// cycle and the physics.
#pragma once

#include <condition_variable>
#include <mutex>
#include <thread>

#include "control/locomotion/convex_mpc.hpp"

namespace cerebellum {

class MpcWorker {
 public:
  explicit MpcWorker(ConvexMpc& mpc);
  ~MpcWorker();
  MpcWorker(const MpcWorker&) = delete;
  MpcWorker& operator=(const MpcWorker&) = delete;

  // start a solve; a solve still running is waited for first
  void post(const MpcInput& input);
  // true when a posted solve exists: waits for it and copies its output
  bool take(MpcOutput& output);

 private:
  void run();

  ConvexMpc& mpc_;
  std::mutex mutex_;
  std::condition_variable wake_;
  MpcInput input_;
  MpcOutput output_;
  bool pending_ = false;  // posted, not yet solved
  bool ready_ = false;    // solved, not yet taken
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace cerebellum
