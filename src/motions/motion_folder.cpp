#include "motions/motion_folder.hpp"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <utility>
#include <vector>

#include "core/text_file.hpp"
#include "motions/motion_file.hpp"

namespace cerebellum {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kMaxFilesPerFolder = 200;

std::string read_text(const fs::path& file) {
  std::string error;
  std::optional<std::string> text = read_text_file(file.string(), kMaxMotionFileBytes, error);
  if (!text) throw MotionFileError(file.string() + ": " + error);
  return std::move(*text);
}

}  // namespace

void load_motion_folder(const std::string& folder, int first_id, int last_id, MotionLibrary& library) {
  std::error_code error;
  if (!fs::is_directory(folder, error)) throw MotionFileError(folder + ": is not a folder of motion files");
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, error)) {
    if (entry.path().extension() != ".toml") continue;
    if (!entry.is_regular_file()) throw MotionFileError(entry.path().string() + ": is not a file");
    files.push_back(entry.path());
    if (files.size() > kMaxFilesPerFolder) {
      throw MotionFileError(folder + ": holds more than " + std::to_string(kMaxFilesPerFolder) + " motion files");
    }
  }
  if (error) throw MotionFileError(folder + ": cannot be listed: " + error.message());
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    MotionFileParse parse = parse_motion_file(read_text(file));
    if (!parse.motion) throw MotionFileError(file.string() + ": " + parse.error);
    Motion& motion = *parse.motion;
    if (motion.id < first_id || motion.id > last_id) {
      throw MotionFileError(file.string() + ": id " + std::to_string(motion.id) + " is outside this folder's ids [" +
                            std::to_string(first_id) + ", " + std::to_string(last_id) + "]");
    }
    motion.origin = file.string();
    // the user gait's files are named relative to the motion file
    for (std::string* path : {&motion.user_gait_definition, &motion.user_gait_parameters}) {
      if (!path->empty() && fs::path(*path).is_relative())
        *path = (file.parent_path() / *path).lexically_normal().string();
    }
    if (const Motion* other = library.find(motion.id)) {
      throw MotionFileError(file.string() + ": id " + std::to_string(motion.id) + " is taken by " + other->origin);
    }
    library.add(std::move(motion));
  }
}

MotionLibrary load_motion_library(const MotionFolders& folders) {
  MotionLibrary library;
  load_motion_folder(folders.folder, kFirstBuiltInMotionId, kLastBuiltInMotionId, library);
  if (!folders.user_folder.empty()) {
    load_motion_folder(folders.user_folder, kFirstUserMotionId, kLastUserMotionId, library);
  }
  return library;
}

}  // namespace cerebellum
