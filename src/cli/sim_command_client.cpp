#include "cli/sim_command_client.hpp"

#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <cstdio>
#include <optional>
#include <random>
#include <stdexcept>

#include "core/number_text.hpp"
#include "io/lcm_common/lcm_url.hpp"
#include "io/lcm_highlevel/lcm_highlevel_config.hpp"
#include "io/lcm_sim_control/sim_control_adapter.hpp"
#include "sim_command_lcmt.hpp"
#include "sim_command_result_lcmt.hpp"

namespace cerebellum {

int send_sim_command(const std::string& url, const std::string& text, double timeout_s, const char* verb) {
  try {
    std::unique_ptr<lcm::LCM> lcm = open_lcm_url(url, verb);
    std::optional<sim_command_result_lcmt> answer;
    std::random_device entropy;
    const std::int64_t request_id = (static_cast<std::int64_t>(entropy()) << 31) ^ entropy();
    struct Handler {
      std::int64_t id;
      std::optional<sim_command_result_lcmt>* answer;
      void on_result(const lcm::ReceiveBuffer*, const std::string&, const sim_command_result_lcmt* result) {
        if (result->request_id == id) *answer = *result;
      }
    } handler{request_id, &answer};
    lcm->subscribe(kSimCommandResultChannel, &Handler::on_result, &handler);
    sim_command_lcmt command;
    command.request_id = request_id;
    command.command = text;
    lcm->publish(kSimCommandChannel, &command);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    while (!answer && std::chrono::steady_clock::now() < deadline) handle_pending(*lcm, 50);
    if (!answer) {
      std::fprintf(stderr,
                   "cerebellum %s: no simulation answered on %s within %g s (is `cerebellum sim` running, in "
                   "this network namespace?)\n",
                   verb, url.c_str(), timeout_s);
      return 1;
    }
    std::printf("%s\n", answer->reason.c_str());
    return answer->result == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cerebellum %s: %s\n", verb, e.what());
    return 1;
  }
}

bool take_sim_verb_option(const std::vector<std::string>& args, std::size_t& i, SimVerbRequest& request) {
  const std::string& arg = args[i];
  const auto value = [&]() -> const std::string& {
    if (i + 1 >= args.size()) throw std::invalid_argument(arg + " needs a value");
    return args[++i];
  };
  if (arg == "--help" || arg == "-h") {
    request.help = true;
  } else if (arg == "--url") {
    request.url = value();
    if (const std::string problem = lcm_url_problem(request.url); !problem.empty()) {
      throw std::invalid_argument("--url: " + problem);
    }
  } else if (arg == "--timeout") {
    const std::string& text = value();
    request.timeout_s = finite_number(text).value_or(-1.0);
    if (!(request.timeout_s > 0.0 && request.timeout_s <= 60.0)) {
      throw std::invalid_argument("--timeout must be in (0, 60] s, got " + text);
    }
  } else {
    return false;
  }
  return true;
}

int run_sim_verb(const char* verb, const std::vector<std::string>& args,
                 SimVerbRequest (*parse)(const std::vector<std::string>&), std::string (*usage)()) {
  SimVerbRequest request;
  try {
    request = parse(args);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "cerebellum %s: %s\n%s", verb, e.what(), usage().c_str());
    return 2;
  }
  if (request.help) {
    std::fputs(usage().c_str(), stdout);
    return 0;
  }
  return send_sim_command(request.url, request.text, request.timeout_s, verb);
}

}  // namespace cerebellum
