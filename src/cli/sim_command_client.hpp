// The client side of the simulation's control channel: send one command text, wait for the
// simulation's answer, print it. Shared by the `push` and `fault` verbs.
#pragma once

#include <string>
#include <vector>

namespace cerebellum {

// 0: the simulation took it (its answer printed on stdout); 1: refused (the reason printed) or no
// simulation answered within timeout_s; verb names the messages
int send_sim_command(const std::string& url, const std::string& text, double timeout_s, const char* verb);

// what a verb's arguments ask for: the command text, where to send it, or only the help
struct SimVerbRequest {
  std::string text;
  std::string url;
  double timeout_s = 2.0;
  bool help = false;
};

// the options every such verb takes: --help, --url URL, --timeout S (in (0, 60]); true when
// args[i] was one (i then points at its last word); throws std::invalid_argument for a bad value
bool take_sim_verb_option(const std::vector<std::string>& args, std::size_t& i, SimVerbRequest& request);

// a verb of the simulation's channel: parse (throws std::invalid_argument: the message and the
// usage on stderr, 2), --help (the usage on stdout, 0), else send_sim_command
int run_sim_verb(const char* verb, const std::vector<std::string>& args,
                 SimVerbRequest (*parse)(const std::vector<std::string>&), std::string (*usage)());

}  // namespace cerebellum
