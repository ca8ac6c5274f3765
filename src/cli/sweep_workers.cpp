#include "cli/sweep_workers.hpp"

#include "cli/child_process.hpp"

#include <sys/wait.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <map>
#include <stdexcept>

namespace cerebellum {

namespace {

std::string how_it_ended(int status) {
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    return std::string("killed by signal ") + std::to_string(signal) + " (" + ::strsignal(signal) + ")";
  }
  return "exit status " + std::to_string(WEXITSTATUS(status)) + " without a result";
}

// the worker's output is its cell's log
pid_t start_worker(const std::string& executable, const std::string& scenario_path, const SweepFolder& folder,
                   std::uint64_t cell) {
  return spawn_with_output({executable, "sweep", scenario_path, "--cell", std::to_string(cell), "--out", folder.dir()},
                           folder.log_path(cell));
}

}  // namespace

std::string own_executable() {
  std::error_code error;
  const auto path = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) throw std::runtime_error("cannot find the program's own file (/proc/self/exe): " + error.message());
  return path.string();
}

void run_cell_workers(const std::string& executable, const std::string& scenario_path, const SweepFolder& folder,
                      const std::vector<std::uint64_t>& cells, int jobs, const WorkerDone& done) {
  std::map<pid_t, std::uint64_t> running;
  std::size_t next = 0;
  while (next < cells.size() || !running.empty()) {
    while (next < cells.size() && static_cast<int>(running.size()) < jobs) {
      running[start_worker(executable, scenario_path, folder, cells[next])] = cells[next];
      ++next;
    }
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, 0);
    if (pid < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(std::string("waiting for the workers failed: ") + std::strerror(errno));
    }
    const auto at = running.find(pid);
    if (at == running.end()) continue;  // not one of ours
    const std::uint64_t cell = at->second;
    running.erase(at);
    // a run that ended badly still has its result (exit status 1); no result is a crash
    const bool ok = folder.finished(cell);
    done(cell, ok ? "" : how_it_ended(status));
  }
}

}  // namespace cerebellum
