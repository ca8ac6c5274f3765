#include "cli/stop_signal.hpp"

#include <pthread.h>
#include <signal.h>

namespace cerebellum {

StopSignal::StopSignal() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  sigaddset(&set, SIGUSR1);  // used by the destructor to wake the watcher
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  watcher_ = std::thread([this, set] {
    int received = 0;
    sigwait(&set, &received);
    stop_.store(true);
    watcher_done_.store(true);
  });
}

StopSignal::~StopSignal() {
  if (!watcher_done_.load()) pthread_kill(watcher_.native_handle(), SIGUSR1);
  watcher_.join();
}

}  // namespace cerebellum
