// The client side of the simulation's control channel: send one command text, wait for the
// simulation's answer, print it. Shared by the `push` and `fault` verbs.
#pragma once

#include <string>

namespace cerebellum {

// 0: the simulation took it (its answer printed on stdout); 1: refused (the reason printed) or no
// simulation answered within timeout_s; verb names the messages
int send_sim_command(const std::string& url, const std::string& text, double timeout_s, const char* verb);

}  // namespace cerebellum
