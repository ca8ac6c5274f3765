// Starting a program of the sweep (a worker, sbatch, scontrol) with its output into files and
// nothing on its input, and waiting for one.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace cerebellum {

// argv[0] is the program's path; err_path empty: stderr into out_path too. Throws
// std::runtime_error when it cannot be started
pid_t spawn_with_output(std::vector<std::string> argv, const std::string& out_path, const std::string& err_path = "");

// its exit status, or 128 + the signal that ended it
int exit_code(int wait_status);

}  // namespace cerebellum
