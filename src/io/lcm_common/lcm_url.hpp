// Opening an LCM URL for an adapter, with an error that says how to fix the usual cause.
#pragma once

#include <memory>
#include <string>

namespace lcm {
class LCM;
}  // namespace lcm

namespace cerebellum {

// throws std::runtime_error naming the interface, the url and the fix when LCM cannot open it
// (most often: no multicast route on this host)
std::unique_ptr<lcm::LCM> open_lcm_url(const std::string& url, const char* interface_name);

// the most packets one call of handle_pending takes: an adapter's step must return to its other
// duties (publishing, logging, seeing that it is asked to stop) whatever a client sends; a flood
// waits in the socket, where the kernel drops what does not fit
inline constexpr int kMaxPacketsPerHandle = 64;

// handles the packets that have arrived, at most kMaxPacketsPerHandle: waits up to timeout_ms for
// the first, then takes the rest without waiting; returns how many were handled
int handle_pending(lcm::LCM& lcm, int timeout_ms);

}  // namespace cerebellum
