// The simulation's own control channel (never the MC's): `sim_command` in, `sim_command_result`
// out, on the odometry URL. Only `cerebellum sim` builds it, on a Simulation handle, so a real
// robot has no such channel. Each command is checked (fingerprint, size, text, limits), applied
// through the Simulation (its thread-safe request mailbox) and answered; refusals are counted and
// logged at a limited rate.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "backend/fault_injecting_backend.hpp"
#include "backend/simulation.hpp"
#include "io/common/adapter_thread.hpp"
#include "io/common/count.hpp"
#include "io/common/link_faults.hpp"
#include "io/common/rate_limited_log.hpp"

namespace lcm {
class LCM;
struct ReceiveBuffer;
}  // namespace lcm

namespace cerebellum {

inline constexpr const char* kSimCommandChannel = "sim_command";
inline constexpr const char* kSimCommandResultChannel = "sim_command_result";

struct SimControlCounters {
  Count taken;
  Count refused;    // well-formed packets with a command the simulation does not do
  Count malformed;  // wrong fingerprint, truncated, oversized
};

class SimControlAdapter {
 public:
  // simulation: nullptr on a real robot, where every command is refused with the reason (so
  // `cerebellum push` and `fault` say why instead of waiting for an answer that never comes);
  // faults: the robot's fault injector, links: the client links' faults, or nullptr (such fault
  // commands are then refused); throws std::runtime_error naming a url LCM cannot open
  SimControlAdapter(Simulation* simulation, FaultInjectingBackend* faults, LinkFaultSet* links, const std::string& url,
                    std::FILE* log);
  ~SimControlAdapter();
  SimControlAdapter(const SimControlAdapter&) = delete;
  SimControlAdapter& operator=(const SimControlAdapter&) = delete;

  SimControlCounters counters() const;
  // stops the thread; prints one summary line
  void finish(std::FILE* out);

 private:
  void step();
  void on_command(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void answer(std::int64_t request_id, bool taken, const std::string& reason);

  Simulation* simulation_;
  FaultInjectingBackend* faults_;
  LinkFaultSet* links_;
  std::FILE* log_;
  std::unique_ptr<lcm::LCM> lcm_;
  RateLimitedLog log_lines_;
  SimControlCounters counts_;  // the adapter's thread counts, anyone reads
  bool finished_ = false;
  // last member: started once everything above is built, stopped first
  AdapterThread thread_;
};

}  // namespace cerebellum
