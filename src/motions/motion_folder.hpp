// The motions of a folder: every *.toml file in it is a motion file (motions/motion_file.hpp).
#pragma once

#include <stdexcept>
#include <string>

#include "modes/motion.hpp"

namespace cerebellum {

// raised for a folder or file that cannot be used; the message names the file and the problem
class MotionFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// where the MC reads its motions: its own (ids 1..79) and the users' (ids 80..100; empty: none)
struct MotionFolders {
  std::string folder;
  std::string user_folder;
};

// the motions of both folders
MotionLibrary load_motion_library(const MotionFolders& folders);

// adds the folder's motions to the library; their ids must lie in [first_id, last_id] and be new
void load_motion_folder(const std::string& folder, int first_id, int last_id, MotionLibrary& library);

}  // namespace cerebellum
