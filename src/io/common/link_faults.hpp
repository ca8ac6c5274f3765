// Faults on a client's link, for the simulation: incoming packets of one interface (for the shared
// memory: its command frames) dropped, delayed, duplicated or corrupted (one byte changed) with
// given probabilities, between the socket (the memory) and the interface's decoder. Set from any
// thread (the simulation's control channel), applied in the thread that takes the packets (the
// adapter's; the loop's for the shared memory); never built for a real robot.
//   link highlevel|motor_sdk|aliengo|shm drop P | delay SECONDS | duplicate P | corrupt P
//   link NAME clear
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace cerebellum {

enum class Link { HighLevel, MotorSdk, AlienGo, Shm };
inline constexpr std::array<const char*, 4> kLinkNames{"highlevel", "motor_sdk", "aliengo", "shm"};

// the names joined: link_names("|") gives "highlevel|motor_sdk|aliengo|shm"
std::string link_names(const std::string& separator);

struct LinkFaultSettings {
  double drop = 0.0;       // probability a packet is lost
  double duplicate = 0.0;  // probability it arrives twice
  double corrupt = 0.0;    // probability one of its bytes is changed
  double delay_s = 0.0;    // every packet arrives this much later
};

struct LinkFaultRequest {
  Link link = Link::HighLevel;
  std::string field;  // "drop", "delay", "duplicate", "corrupt" or "clear": the setting it changes
  double value = 0.0;
};

struct LinkFaultParse {
  std::optional<LinkFaultRequest> request;
  std::string error;
};

// the words after "fault" starting with "link"; the request changes one field of current
LinkFaultParse parse_link_fault(const std::vector<std::string>& words);
std::string link_fault_text(const LinkFaultRequest& request);

struct LinkFaultCounters {
  std::uint64_t dropped = 0;
  std::uint64_t duplicated = 0;
  std::uint64_t corrupted = 0;
  std::uint64_t delayed = 0;
  std::uint64_t overflowed = 0;  // delayed packets lost because too many were waiting
};

class LinkFaults {
 public:
  using Deliver = std::function<void(const std::uint8_t* data, std::size_t size)>;

  explicit LinkFaults(unsigned seed = 1);
  // any thread: change one field (or clear all) of the settings
  void apply(const LinkFaultRequest& request);
  LinkFaultSettings settings() const;
  // the adapter thread: a packet arrived at now_s (any monotonic seconds); deliver gets what the
  // decoder should see now (nothing, the packet, a corrupted copy, or two copies)
  void pass(const std::uint8_t* data, std::size_t size, double now_s, const Deliver& deliver);
  // the adapter thread, every step: the delayed packets that are due
  void release(double now_s, const Deliver& deliver);
  LinkFaultCounters counters() const;

 private:
  struct Delayed {
    double due_s;
    std::vector<std::uint8_t> bytes;
  };
  void deliver_now(std::vector<std::uint8_t>& bytes, const LinkFaultSettings& settings, const Deliver& deliver);

  mutable std::mutex mutex_;
  LinkFaultSettings settings_;
  LinkFaultCounters counters_;
  std::mt19937 rng_;
  std::deque<Delayed> delayed_;
};

// the adapter thread: a packet that arrived, through the link's faults when it has any
// (faults == nullptr: straight to deliver), and the delayed ones that are due
void receive_through(LinkFaults* faults, const std::uint8_t* data, std::size_t size, double now_s,
                     const LinkFaults::Deliver& deliver);
void release_due(LinkFaults* faults, double now_s, const LinkFaults::Deliver& deliver);

// one per interface, owned by the simulation command and lent to the adapters
struct LinkFaultSet {
  LinkFaults highlevel{1};
  LinkFaults motor_sdk{2};
  LinkFaults aliengo{3};
  LinkFaults shm{4};
  LinkFaults& of(Link link) {
    switch (link) {
      case Link::HighLevel: return highlevel;
      case Link::MotorSdk: return motor_sdk;
      case Link::AlienGo: return aliengo;
      case Link::Shm: break;
    }
    return shm;
  }
};

}  // namespace cerebellum
