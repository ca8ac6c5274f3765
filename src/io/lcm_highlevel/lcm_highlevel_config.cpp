#include "io/lcm_highlevel/lcm_highlevel_config.hpp"

#include <algorithm>
#include <charconv>
#include <string_view>

namespace cerebellum {
namespace {

constexpr std::string_view kScheme = "udpm://";

// a decimal number in [lower, upper], the whole text
bool parse_bounded(std::string_view text, long lower, long upper, long& value) {
  if (text.empty()) return false;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size() && value >= lower && value <= upper;
}

std::string quoted(std::string_view text) { return std::string(1, '\'').append(text).append(1, '\''); }

std::string ipv4_multicast_problem(std::string_view address) {
  long octets[4] = {};
  std::size_t start = 0;
  for (int i = 0; i < 4; ++i) {
    const std::size_t dot = i < 3 ? address.find('.', start) : address.size();
    if (dot == std::string_view::npos || !parse_bounded(address.substr(start, dot - start), 0, 255, octets[i])) {
      return quoted(address) + " is not an IPv4 address";
    }
    start = dot + 1;
  }
  if (octets[0] < 224 || octets[0] > 239) return quoted(address) + " is not a multicast group (224..239.x.x.x)";
  return {};
}

std::string options_problem(std::string_view options) {
  std::size_t start = 0;
  while (start <= options.size()) {
    const std::size_t end = std::min(options.find('&', start), options.size());
    const std::string_view option = options.substr(start, end - start);
    const std::size_t equals = option.find('=');
    if (equals == std::string_view::npos || equals == 0) return "option '" + std::string(option) + "' is not key=value";
    long ttl = 0;
    if (option.substr(0, equals) == "ttl" && !parse_bounded(option.substr(equals + 1), 0, 255, ttl)) {
      return "ttl must be an integer in [0, 255]";
    }
    start = end + 1;
  }
  return {};
}

}  // namespace

std::string lcm_url_problem(const std::string& url) {
  const std::string_view text(url);
  if (text.substr(0, kScheme.size()) != kScheme) return "must start with udpm://";
  const std::string_view rest = text.substr(kScheme.size());
  const std::size_t question = rest.find('?');
  const std::string_view network = rest.substr(0, question);
  const std::size_t colon = network.rfind(':');
  if (colon == std::string_view::npos) return "needs <group>:<port> after udpm://";
  if (std::string problem = ipv4_multicast_problem(network.substr(0, colon)); !problem.empty()) return problem;
  long port = 0;
  if (!parse_bounded(network.substr(colon + 1), 1, 65535, port)) return "port must be an integer in [1, 65535]";
  if (question == std::string_view::npos) return {};
  return options_problem(rest.substr(question + 1));
}

}  // namespace cerebellum
