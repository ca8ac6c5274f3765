#include "cli/log_command.hpp"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <exception>
#include <stdexcept>
#include <thread>

#include "cli/log_options.hpp"
#include "cli/log_replay.hpp"
#include "cli/stop_signal.hpp"

extern char** environ;

namespace cerebellum {
namespace {

std::string default_prefix() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char text[64];
  std::strftime(text, sizeof text, "cerebellum-%Y%m%d-%H%M%S", &local);
  return text;
}

// starts argv[0] from PATH with SIGINT and SIGTERM unblocked (StopSignal blocks them here)
pid_t spawn(const std::vector<std::string>& command) {
  std::vector<char*> argv;
  for (const std::string& arg : command) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK);
  pid_t child = -1;
  const int error = posix_spawnp(&child, argv[0], nullptr, &attributes, argv.data(), environ);
  posix_spawnattr_destroy(&attributes);
  if (error == ENOENT) throw std::runtime_error(command[0] + " not found on PATH (Debian package: liblcm-bin)");
  if (error != 0) throw std::runtime_error("cannot start " + command[0] + ": " + std::strerror(error));
  return child;
}

bool exited_cleanly(int status) {
  return (WIFEXITED(status) && WEXITSTATUS(status) == 0) || (WIFSIGNALED(status) && WTERMSIG(status) == SIGINT);
}

struct Logger {
  int port = 0;
  std::string path;
  pid_t pid = -1;
  bool running = true;
  int status = 0;
};

}  // namespace

int run_log_command(const std::vector<std::string>& args) {
  LogOptions options;
  try {
    options = parse_log_options(args);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cerebellum log: %s\n", e.what());
    return 2;
  }
  if (options.help) {
    std::fputs(log_usage().c_str(), stdout);
    return 0;
  }
  if (options.prefix.empty()) options.prefix = default_prefix();

  StopSignal stop;
  std::vector<Logger> loggers;
  bool failed = false;
  try {
    for (int port : options.ports) {
      Logger logger;
      logger.port = port;
      logger.path = log_file_path(options.prefix, port);
      logger.pid = spawn(logger_command(options.prefix, port, options.force));
      std::printf("log: %s -> %s\n", lcm_url(port, 0).c_str(), logger.path.c_str());
      loggers.push_back(logger);
    }
    std::printf("log: recording %zu port(s); Ctrl-C to stop\n", loggers.size());
    std::fflush(stdout);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cerebellum log: %s\n", e.what());
    failed = true;
  }

  // until Ctrl-C, or until a logger ends by itself (it has said why)
  while (!failed && !stop.flag().load()) {
    for (Logger& logger : loggers) {
      if (waitpid(logger.pid, &logger.status, WNOHANG) == logger.pid) {
        logger.running = false;
        failed = true;
        std::fprintf(stderr, "cerebellum log: lcm-logger for port %d stopped; stopping the others\n", logger.port);
      }
    }
    if (!failed) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  for (Logger& logger : loggers) {
    if (logger.running) kill(logger.pid, SIGINT);
  }
  for (Logger& logger : loggers) {
    if (!logger.running) continue;
    while (waitpid(logger.pid, &logger.status, 0) < 0 && errno == EINTR) {
    }
    logger.running = false;
    if (!exited_cleanly(logger.status)) failed = true;
  }
  for (const Logger& logger : loggers) {
    if (!exited_cleanly(logger.status)) continue;
    try {
      std::printf("log: %s: %llu events\n", logger.path.c_str(),
                  static_cast<unsigned long long>(count_log_events(logger.path)));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "cerebellum log: %s\n", e.what());
      failed = true;
    }
  }
  return failed ? 1 : 0;
}

int run_replay_command(const std::vector<std::string>& args) {
  ReplayOptions options;
  std::vector<PortLog> logs;
  try {
    options = parse_replay_options(args);
    if (options.help) {
      std::fputs(replay_usage().c_str(), stdout);
      return 0;
    }
    logs = find_port_logs(options.prefix, options.ports);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cerebellum replay: %s\n", e.what());
    return 2;
  }
  StopSignal stop;
  try {
    for (const PortLog& log : logs) {
      std::printf("replay: %s -> %s\n", log.path.c_str(), lcm_url(log.port, options.ttl).c_str());
    }
    std::fflush(stdout);
    const ReplayResult result = replay_port_logs(logs, options.speed, options.ttl, stop.flag());
    std::printf("replay: %llu events over %.2f s of recorded time%s\n", static_cast<unsigned long long>(result.events),
                result.log_span_s, result.stopped ? " (stopped)" : "");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cerebellum replay: %s\n", e.what());
    return 1;
  }
  return 0;
}

}  // namespace cerebellum
