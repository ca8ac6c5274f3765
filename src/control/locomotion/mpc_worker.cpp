#include "control/locomotion/mpc_worker.hpp"

namespace cerebellum {

MpcWorker::MpcWorker(ConvexMpc& mpc) : mpc_(mpc), thread_([this] { run(); }) {}

MpcWorker::~MpcWorker() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void MpcWorker::post(const MpcInput& input) {
  std::unique_lock lock(mutex_);
  wake_.wait(lock, [this] { return !pending_; });
  input_ = input;
  pending_ = true;
  ready_ = false;
  lock.unlock();
  wake_.notify_all();
}

bool MpcWorker::take(MpcOutput& output) {
  std::unique_lock lock(mutex_);
  if (!pending_ && !ready_) return false;
  wake_.wait(lock, [this] { return ready_; });
  output = output_;
  ready_ = false;
  return true;
}

void MpcWorker::run() {
  std::unique_lock lock(mutex_);
  while (true) {
    wake_.wait(lock, [this] { return stopping_ || pending_; });
    if (stopping_) return;
    const MpcInput input = input_;
    lock.unlock();
    const MpcOutput output = mpc_.solve(input);
    lock.lock();
    output_ = output;
    pending_ = false;
    ready_ = true;
    wake_.notify_all();
  }
}

}  // namespace cerebellum
