// The user gaits that named motions bring with them (a motion file's user_gait = {definition,
// parameters}): read, converted from the human form when needed, checked as an uploaded gait is,
// and attached to their motion as a program. Called once at start.
#pragma once

#include <memory>
#include <string>

#include "modes/motion.hpp"

namespace cerebellum {

// the program of a definition file and a parameters file (human or uploaded form); throws
// std::invalid_argument naming the file and the problem
std::shared_ptr<const UserGaitProgram> load_user_gait_files(const std::string& definition_path,
                                                            const std::string& parameters_path);

// every motion of the library that names a user gait gets its program
void attach_user_gaits(MotionLibrary& library);

}  // namespace cerebellum
