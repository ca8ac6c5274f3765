// `cerebellum run`: the MC on the robot its configuration names (robot.kind), paced by the wall
// clock, serving the client interfaces the configuration enables.
#pragma once

#include <string>
#include <vector>

namespace cerebellum {

int run_run_command(const std::vector<std::string>& args);

}  // namespace cerebellum
