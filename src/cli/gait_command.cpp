#include "cli/gait_command.hpp"

#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <cstdio>
#include <optional>

#include "cli/cmd_options.hpp"
#include "core/text_file.hpp"
#include "file_send_lcmt.hpp"
#include "io/lcm_highlevel/highlevel_wire.hpp"
#include "motions/user_gait_convert.hpp"
#include "motions/user_gait_file.hpp"
#include "motions/user_gait_program.hpp"

namespace cerebellum {
namespace {

constexpr const char* kUsage =
    "usage: cerebellum gait convert PARAMS.toml\n"
    "       cerebellum gait upload DEFINITION.toml PARAMS.toml [--ttl N] [--timeout S]\n"
    "  convert  print the uploaded form of human-form gait parameters (type = \"usergait\", ...)\n"
    "  upload   send both files on user_gait_file (parameters converted when in the human form) and\n"
    "           print the MC's result for each; exit 0 when both are 0. The reason for a 1 is\n"
    "           printed from the same checks the MC runs (the answer carries only the number)\n"
    "  --ttl N      multicast ttl, 0..255 (default 255; 0 keeps packets on this host)\n"
    "  --timeout S  wait at most S s for each answer (default 2)\n";

// a gait file as the MC would take it (at most its size limit); prints why not
std::optional<std::string> read_gait_file(const char* verb, const std::string& path) {
  std::string error;
  std::optional<std::string> text = read_text_file(path, kMaxUserGaitFileBytes, error);
  if (!text) std::fprintf(stderr, "cerebellum gait %s: %s: %s\n", verb, path.c_str(), error.c_str());
  return text;
}

// why the MC would refuse the text (the checks of the adapter), or ""
std::string refusal_reason(const std::string& text) {
  const UserGaitParse parsed = parse_user_gait_file(text);
  if (!parsed.file) return parsed.error;
  return user_gait_file_problem(*parsed.file);
}

class ResultListener {
 public:
  void on_result(const lcm::ReceiveBuffer*, const std::string&, const file_recv_lcmt* message) {
    result_ = message->result;
  }
  std::optional<int> take() {
    const std::optional<int> result = result_;
    result_.reset();
    return result;
  }

 private:
  std::optional<int> result_;
};

// publishes one file and waits for its answer; returns the MC's result or nullopt on timeout
std::optional<int> send_file(lcm::LCM& lcm, ResultListener& listener, const std::string& text, double timeout_s) {
  file_send_lcmt message;
  message.data = text;
  listener.take();
  if (lcm.publish(kUserGaitFileChannel, &message) != 0) return std::nullopt;
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < until) {
    lcm.handleTimeout(50);
    if (const std::optional<int> result = listener.take()) return result;
  }
  return std::nullopt;
}

int convert(const std::string& path) {
  const std::optional<std::string> text = read_gait_file("convert", path);
  if (!text) return 2;
  const UserGaitConversion converted = convert_gait_parameters(*text);
  if (!converted.error.empty()) {
    std::fprintf(stderr, "cerebellum gait convert: %s: %s\n", path.c_str(), converted.error.c_str());
    return 1;
  }
  std::fputs(converted.text.c_str(), stdout);
  return 0;
}

int upload(const std::vector<std::string>& args) {
  std::vector<std::string> files;
  int ttl = 255;
  double timeout_s = 2.0;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const bool has_value = i + 1 < args.size();
    try {
      if (args[i] == "--ttl" && has_value) {
        ttl = std::stoi(args[++i]);
        if (ttl < 0 || ttl > 255) throw std::out_of_range("ttl");
      } else if (args[i] == "--timeout" && has_value) {
        timeout_s = std::stod(args[++i]);
        if (!(timeout_s > 0.0 && timeout_s <= 60.0)) throw std::out_of_range("timeout");
      } else if (args[i].rfind("--", 0) == 0) {
        throw std::invalid_argument(args[i]);
      } else {
        files.push_back(args[i]);
      }
    } catch (const std::exception&) {
      std::fprintf(stderr, "cerebellum gait upload: bad option or value near '%s'\n%s", args[i].c_str(), kUsage);
      return 2;
    }
  }
  if (files.size() != 2) {
    std::fprintf(stderr, "cerebellum gait upload: give a definition and parameters\n%s", kUsage);
    return 2;
  }
  std::string texts[2];
  for (std::size_t k = 0; k < 2; ++k) {
    const std::optional<std::string> text = read_gait_file("upload", files[k]);
    if (!text) return 2;
    texts[k] = *text;
  }
  if (!is_converted_gait_parameters(texts[1])) {
    const UserGaitConversion converted = convert_gait_parameters(texts[1]);
    if (!converted.error.empty()) {
      std::fprintf(stderr, "cerebellum gait upload: %s: %s\n", files[1].c_str(), converted.error.c_str());
      return 1;
    }
    texts[1] = converted.text;
    std::printf("%s: converted from the human form (%zu bytes)\n", files[1].c_str(), texts[1].size());
  }
  const std::string url = highlevel_url(kCommandPort, ttl);
  lcm::LCM lcm(url);
  if (!lcm.good()) {
    std::fprintf(stderr, "cerebellum gait upload: cannot open LCM on %s\n", url.c_str());
    return 2;
  }
  ResultListener listener;
  lcm.subscribe(kUserGaitResultChannel, &ResultListener::on_result, &listener);
  int failed = 0;
  for (std::size_t k = 0; k < 2; ++k) {
    const std::optional<int> result = send_file(lcm, listener, texts[k], timeout_s);
    if (!result) {
      std::printf("%s: no answer within %.1f s (is the MC running?)\n", files[k].c_str(), timeout_s);
      failed = 1;
      continue;
    }
    if (*result == 0) {
      std::printf("%s: result 0 (stored)\n", files[k].c_str());
      continue;
    }
    failed = 1;
    const std::string reason = refusal_reason(texts[k]);
    std::printf("%s: result %d (refused): %s\n", files[k].c_str(), *result,
                reason.empty() ? "the MC's log says why" : reason.c_str());
  }
  if (failed == 0) std::printf("ready: run it with mode 11 or 62, gait 110\n");
  return failed;
}

}  // namespace

int run_gait_command(const std::vector<std::string>& args) {
  if (args.empty() || args[0] == "--help" || args[0] == "-h") {
    std::fputs(kUsage, args.empty() ? stderr : stdout);
    return args.empty() ? 2 : 0;
  }
  if (args[0] == "convert" && args.size() == 2) return convert(args[1]);
  if (args[0] == "upload") return upload(std::vector<std::string>(args.begin() + 1, args.end()));
  std::fprintf(stderr, "cerebellum gait: unknown use\n%s", kUsage);
  return 2;
}

}  // namespace cerebellum
