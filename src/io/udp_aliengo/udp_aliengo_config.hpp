// Configuration of the AlienGo high-level UDP interface (config section `aliengo:`; the sport
// session's timers of the same section are the MC's: McConfig::aliengo_session).
#pragma once

#include <string>

namespace cerebellum {

inline constexpr int kAlienGoDefaultPort = 8082;

struct AlienGoUdpConfig {
  bool enabled = true;
  // this host only by default; 0.0.0.0 (or the robot's 192.168.123.220) serves other machines
  std::string bind_address = "127.0.0.1";
  int port = kAlienGoDefaultPort;
};

}  // namespace cerebellum
