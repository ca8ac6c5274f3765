#include "cli/sweep_slurm.hpp"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "cli/child_process.hpp"
#include "cli/progress_bar.hpp"
#include "cli/sweep_workers.hpp"
#include "core/text_file.hpp"

namespace cerebellum {

namespace fs = std::filesystem;

namespace {

constexpr int kDefaultMaxTasks = 100;
constexpr std::size_t kOutputMaxBytes = 64 * 1024;

// the program's path: as given when it names a file, else the first on PATH; empty when none
std::string find_program(const std::string& name) {
  if (name.find('/') != std::string::npos) return ::access(name.c_str(), X_OK) == 0 ? name : "";
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const std::string candidate = (fs::path(dir.empty() ? "." : dir) / name).string();
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

std::string path_words() {
  const char* path = std::getenv("PATH");
  return path ? path : "<unset>";
}

int wait_for(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return exit_code(status);
}

std::string small_file(const std::string& path) {
  std::string error;
  std::string text = read_text_file(path, kOutputMaxBytes, error).value_or("");
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text;
}

// what the controller says, from scontrol beside sbatch: names the controller it tried
std::string controller_answer(const std::string& sbatch, const std::string& slurm_dir) {
  const std::string scontrol = (fs::path(sbatch).parent_path() / "scontrol").string();
  if (::access(scontrol.c_str(), X_OK) != 0) return "no scontrol beside " + sbatch + " to ask the controller";
  const std::string out = slurm_dir + "/scontrol-ping.out";
  const int status = wait_for(spawn_with_output({scontrol, "ping"}, out));
  return scontrol + " ping (exit " + std::to_string(status) + "): " + small_file(out);
}

// the task script: one slice of the grid, with the same program and absolute paths, so the
// task runs the same wherever Slurm starts it
std::string write_task_script(const SweepOptions& o, const SweepFolder& folder, int tasks,
                              const std::string& slurm_dir) {
  const auto quoted = [](const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
  };
  const std::string script = slurm_dir + "/task.sh";
  std::ofstream out(script, std::ios::trunc);
  out << "#!/bin/sh\n"
      << "# one Slurm array task of a cerebellum sweep: the cells K with K % " << tasks << " == the task's id\n"
      << "exec " << quoted(own_executable()) << " sweep " << quoted(fs::absolute(o.file).string()) << " --out "
      << quoted(fs::absolute(folder.dir()).string()) << " --slice \"$SLURM_ARRAY_TASK_ID/" << tasks
      << "\" -j \"${SLURM_CPUS_PER_TASK:-1}\"\n";
  out.close();
  if (!out) throw std::runtime_error("cannot write " + script);
  ::chmod(script.c_str(), 0755);
  return script;
}

}  // namespace

void submit_slurm_sweep(const SweepOptions& o, const SweepFolder& folder, std::uint64_t cells) {
  const SlurmOptions& slurm = *o.slurm;
  const std::string sbatch = find_program(slurm.sbatch);
  if (sbatch.empty())
    throw std::runtime_error("Slurm is not reachable: no program '" + slurm.sbatch + "' " +
                             (slurm.sbatch.find('/') != std::string::npos ? std::string("(not an executable file)")
                                                                          : "on PATH (" + path_words() + ")") +
                             "; install Slurm's client (Debian: slurm-wlm) or give --sbatch PATH");
  const std::string slurm_dir = (fs::path(folder.dir()) / "slurm").string();
  fs::create_directories(slurm_dir);
  const int tasks = static_cast<int>(
      std::min<std::uint64_t>(cells, slurm.tasks > 0 ? static_cast<std::uint64_t>(slurm.tasks) : kDefaultMaxTasks));
  const std::string script = write_task_script(o, folder, tasks, slurm_dir);
  std::vector<std::string> words{sbatch, "--parsable", "--job-name=cerebellum-sweep",
                                 "--array=0-" + std::to_string(tasks - 1),
                                 "--output=" + fs::absolute(slurm_dir).string() + "/task-%a.out",
                                 "--chdir=" + fs::absolute(folder.dir()).string()};
  if (!slurm.partition.empty()) words.push_back("--partition=" + slurm.partition);
  if (!slurm.time_limit.empty()) words.push_back("--time=" + slurm.time_limit);
  if (slurm.wait) words.push_back("--wait");
  words.push_back(script);
  const std::string out = slurm_dir + "/sbatch.out", err = slurm_dir + "/sbatch.err";
  const pid_t pid = spawn_with_output(words, out, err);

  // sbatch prints the job's id once the controller took it; --wait then holds until the array ends
  ProgressBar bar(stdout, "slurm");
  const auto start = std::chrono::steady_clock::now();
  std::string job;
  int status = -1;
  for (;;) {
    int raw = 0;
    const pid_t ended = ::waitpid(pid, &raw, WNOHANG);
    if (job.empty()) job = small_file(out);
    if (ended == pid) {
      status = exit_code(raw);
      break;
    }
    std::uint64_t finished = 0;
    for (std::uint64_t cell = 0; cell < cells; ++cell) finished += folder.finished(cell);
    bar.update(finished, cells, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
               job.empty() ? "submitting" : "job " + job);
    // each look stats every cell file, maybe on a shared file system: not too often
    std::this_thread::sleep_for(std::chrono::seconds(2));
  }
  bar.finish();
  if (job.empty()) {
    throw std::runtime_error("Slurm is not reachable: " + sbatch + " failed (exit " + std::to_string(status) +
                             "): " + small_file(err) + "; the controller: " + controller_answer(sbatch, slurm_dir));
  }
  std::ofstream(slurm_dir + "/jobs", std::ios::app) << job << "\n";
  std::fprintf(stderr, "cerebellum sweep: Slurm job %s, %d array tasks, output in %s\n", job.c_str(), tasks,
               slurm_dir.c_str());
  // with --wait, sbatch's own status is the array's: a task with a crashed cell ends non-zero,
  // and the gathering that follows says which
}

void print_slurm_jobs(const SweepFolder& folder) {
  const std::string jobs = small_file((fs::path(folder.dir()) / "slurm" / "jobs").string());
  if (jobs.empty()) return;
  std::string listed = jobs;
  std::replace(listed.begin(), listed.end(), '\n', ' ');
  std::printf("Slurm job(s) %s (squeue -j <id> for their state; task output in %s/slurm/)\n", listed.c_str(),
              folder.dir().c_str());
}

}  // namespace cerebellum
