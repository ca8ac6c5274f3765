#include "io/lcm_common/lcm_url.hpp"

#include <lcm/lcm-cpp.hpp>

#include <stdexcept>

namespace cerebellum {

std::unique_ptr<lcm::LCM> open_lcm_url(const std::string& url, const char* interface_name) {
  auto lcm = std::make_unique<lcm::LCM>(url);
  if (!lcm->good()) {
    throw std::runtime_error(std::string(interface_name) + ": cannot open LCM url " + url +
                             ". LCM needs a multicast route: as root, `ip route add 224.0.0.0/4 dev lo` "
                             "(this host only) or `dev <your interface>` (see README, Troubleshooting)");
  }
  return lcm;
}

int handle_pending(lcm::LCM& lcm, int timeout_ms) {
  int handled = 0;
  if (lcm.handleTimeout(timeout_ms) <= 0) return 0;
  ++handled;
  while (handled < kMaxPacketsPerHandle && lcm.handleTimeout(0) > 0) ++handled;
  return handled;
}

}  // namespace cerebellum
