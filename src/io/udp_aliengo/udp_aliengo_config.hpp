// Configuration of the AlienGo high-level UDP interface (config section `aliengo:`).
#pragma once

#include <string>

#include "modes/aliengo_session.hpp"

namespace cerebellum {

inline constexpr int kAlienGoDefaultPort = 8082;

struct AlienGoUdpConfig {
  bool enabled = true;
  // this host only by default; 0.0.0.0 (or the robot's 192.168.123.220) serves other machines
  std::string bind_address = "127.0.0.1";
  int port = kAlienGoDefaultPort;
  AlienGoSessionConfig session;
};

}  // namespace cerebellum
