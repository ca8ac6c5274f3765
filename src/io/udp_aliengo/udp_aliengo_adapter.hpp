// The AlienGo high-level interface on UDP. One thread receives HighCmd datagrams (checked and
// decoded here, dropped ones counted per reason), hands each decoded HighCmd to the AlienGo
// client's stage in the tick (AlienGoSource: the sport session's decisions are taken there), and
// answers each datagram's sender with a HighState of the newest cycle. The loop thread only copies
// the cycle's state and reported mode into a ring (on_cycle).
#pragma once

#include <netinet/in.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <string>

#include "core/spsc_ring.hpp"
#include "cycle/cycle_observer.hpp"
#include "io/common/adapter_thread.hpp"
#include "io/common/count.hpp"
#include "io/common/link_faults.hpp"
#include "io/common/rate_limited_log.hpp"
#include "io/udp_aliengo/aliengo_wire.hpp"
#include "io/udp_aliengo/udp_aliengo_config.hpp"
#include "modes/aliengo_inbox.hpp"
#include "modes/client_port.hpp"

namespace cerebellum {

// the adapter's thread counts the first ones; the last four are the AlienGo client's figures in
// the machine and its stage, filled in by counters()
struct AlienGoCounters {
  Count received;  // datagrams
  Count accepted;  // good HighCmd frames
  Count wrong_length;
  Count bad_crc;
  Count low_level;
  Count non_finite;
  Count states_sent;
  Count send_errors;
  Count illegal_moves;       // refused by the vendor's mode table (the robot stays)
  Count refused_not_holder;  // the CyberDog2 LCM client held the robot
  Count ring_overflow;       // commands arriving faster than the loop takes them (dropped)
  Count timeouts;            // the client held the robot and fell silent for 0.5 s
};

class UdpAliengoAdapter final : public CycleObserver {
 public:
  // binds the socket and starts the thread; throws std::runtime_error naming the address
  // port: the machine's counters and refusals of this client's commands, for the log; inbox: where
  // decoded HighCmds go (the sport session takes them in the tick)
  UdpAliengoAdapter(ClientPort port, AlienGoInbox& inbox, const AlienGoUdpConfig& config, std::FILE* log);
  ~UdpAliengoAdapter() override;
  UdpAliengoAdapter(const UdpAliengoAdapter&) = delete;
  UdpAliengoAdapter& operator=(const UdpAliengoAdapter&) = delete;
  // simulation only: HighCmd datagrams pass these link faults before they are decoded (a delayed
  // one is answered to the newest sender)
  void attach_link_faults(LinkFaults& faults) { link_faults_.store(&faults); }

  // loop thread, after the tick: copy the state and the reported mode for the interface thread
  void on_cycle(const CycleRecord& record) override;

  // stops the thread and prints one summary line to out
  void finish(std::FILE* out);
  AlienGoCounters counters() const;
  // the port actually bound (config port 0: any free port, for tests)
  int port() const { return port_; }

 private:
  struct Snapshot {
    RobotState state;
    int aliengo_mode = 0;      // HighState.mode
    SportFrame aliengo_frame;  // HighState.position is in it
  };

  void step();
  void handle_datagram(const std::uint8_t* data, std::size_t size, const sockaddr_in& sender);
  void answer(const sockaddr_in& sender);
  void take_newest_snapshot();
  void log_refusals(double now_s);
  void log_once_per_second();

  ClientPort client_;
  AlienGoInbox& inbox_;
  std::FILE* log_;
  std::atomic<LinkFaults*> link_faults_{nullptr};
  sockaddr_in newest_sender_{};
  int port_ = 0;  // before socket_: opening the socket sets it
  int socket_ = -1;
  // loop thread -> interface thread
  SpscRing<Snapshot, 8> snapshots_;
  // interface thread
  Snapshot newest_;
  std::array<std::uint8_t, 2048> buffer_{};
  RateLimitedLog refusal_log_;
  double next_count_log_s_ = 0.0;
  std::uint64_t logged_drops_ = 0;
  std::uint64_t logged_not_holder_ = 0;
  std::uint64_t logged_overflow_ = 0;
  std::uint64_t logged_timeouts_ = 0;
  // interface thread -> anyone
  AlienGoCounters counts_;
  // last member: started once everything above is built, stopped first
  AdapterThread thread_;
};

}  // namespace cerebellum
