#include "io/udp_aliengo/udp_aliengo_adapter.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

#include "io/common/count_report.hpp"
#include "io/common/wall_clock.hpp"

namespace cerebellum {
namespace {

constexpr const char* kInterfaceName = "aliengo";
constexpr int kRefusalLinesPerSecond = 5;
constexpr int kPollTimeoutMs = 1;
// a step reads at most this many datagrams before it logs and looks at the loop again: a client
// streaming faster than the thread reads must not keep it in one drain with an old cycle
constexpr int kMaxDatagramsPerStep = 64;

int open_socket(const AlienGoUdpConfig& config, int& bound_port) {
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(config.port));
  if (inet_pton(AF_INET, config.bind_address.c_str(), &address.sin_addr) != 1) {
    throw std::runtime_error("aliengo: bind_address '" + config.bind_address + "' is not an IPv4 address");
  }
  const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
  if (fd < 0) throw std::runtime_error(std::string("aliengo: socket: ") + std::strerror(errno));
  if (::bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    const std::string reason = std::strerror(errno);
    ::close(fd);
    throw std::runtime_error("aliengo: cannot bind UDP " + config.bind_address + ":" + std::to_string(config.port) +
                             ": " + reason + (errno == EADDRNOTAVAIL ? " (the address is not on this machine)" : "") +
                             " (config aliengo.bind_address / aliengo.port)");
  }
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
  socklen_t length = sizeof address;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
  bound_port = ntohs(address.sin_port);
  return fd;
}

}  // namespace

UdpAliengoAdapter::UdpAliengoAdapter(ClientPort port, AlienGoInbox& inbox, const AlienGoUdpConfig& config,
                                     std::FILE* log)
    : client_(port),
      inbox_(inbox),
      log_(log),
      port_(config.port),
      socket_(open_socket(config, port_)),
      refusal_log_(log, kInterfaceName, "HighCmd refusals", kRefusalLinesPerSecond) {
  std::fprintf(log_, "aliengo: HighCmd in, HighState back on UDP %s:%d\n", config.bind_address.c_str(), port_);
  std::fflush(log_);
  thread_.start([this] { step(); });
}

UdpAliengoAdapter::~UdpAliengoAdapter() {
  thread_.stop();
  if (socket_ >= 0) ::close(socket_);
}

void UdpAliengoAdapter::on_cycle(const CycleRecord& record) {
  snapshots_.try_push(Snapshot{record.state, record.high_level.aliengo_mode, record.high_level.aliengo_frame});
}

void UdpAliengoAdapter::take_newest_snapshot() {
  while (std::optional<Snapshot> snapshot = snapshots_.try_pop()) newest_ = *snapshot;
}

void UdpAliengoAdapter::step() {
  pollfd waiting{socket_, POLLIN, 0};
  ::poll(&waiting, 1, kPollTimeoutMs);
  for (int read = 0; read < kMaxDatagramsPerStep; ++read) {
    // each answer carries the newest cycle when its datagram is read
    take_newest_snapshot();
    sockaddr_in sender{};
    socklen_t sender_length = sizeof sender;
    const ssize_t got = ::recvfrom(socket_, buffer_.data(), buffer_.size(), MSG_TRUNC,
                                   reinterpret_cast<sockaddr*>(&sender), &sender_length);
    if (got < 0) break;  // EAGAIN: nothing more
    newest_sender_ = sender;
    const auto size = static_cast<std::size_t>(got);
    // an oversized datagram (MSG_TRUNC) is refused as it is: only what fits is ever copied
    receive_through(size > buffer_.size() ? nullptr : link_faults_.load(), buffer_.data(), size, wall_seconds(),
                    [&](const std::uint8_t* data, std::size_t length) { handle_datagram(data, length, sender); });
  }
  release_due(link_faults_.load(), wall_seconds(),
              [&](const std::uint8_t* data, std::size_t length) { handle_datagram(data, length, newest_sender_); });
  log_refusals(wall_seconds());
  log_once_per_second();
}

void UdpAliengoAdapter::handle_datagram(const std::uint8_t* data, std::size_t size, const sockaddr_in& sender) {
  counts_.received.add();
  AlienGoCommand command;
  // MSG_TRUNC: size is the datagram's real length even when it did not fit the buffer
  const AlienGoDecode decoded =
      size > buffer_.size() ? AlienGoDecode::WrongLength : decode_high_cmd(data, size, command);
  switch (decoded) {
    case AlienGoDecode::Ok: break;
    case AlienGoDecode::WrongLength: counts_.wrong_length.add(); return;
    case AlienGoDecode::BadCrc: counts_.bad_crc.add(); return;
    case AlienGoDecode::LowLevel: counts_.low_level.add(); return;
    case AlienGoDecode::NonFinite: counts_.non_finite.add(); return;
  }
  counts_.accepted.add();
  // the sport session decides in the tick; a full ring (faster than the tick takes) is counted there
  inbox_.push(command);
  answer(sender);
}

void UdpAliengoAdapter::log_refusals(double now_s) {
  while (std::optional<AlienGoRefusal> refusal = inbox_.next_refusal()) {
    char line[160];
    std::snprintf(line, sizeof line, "HighCmd mode %d refused in mode %d: %s", refusal->mode, refusal->session_mode,
                  refusal->reason);
    refusal_log_.line(now_s, line);
  }
  // what the MC refused of the commands the session made (another client holds the robot, a
  // transition the MC does not allow, a protection)
  while (std::optional<ClientNote> note = client_.next_note()) {
    char line[256];
    std::snprintf(line, sizeof line, "the MC %s mode %d gait %d while in mode %d: %s%s%s%s",
                  note->clamped ? "clamped" : "refused", note->mode, note->gait_id, note->from_mode, note->reason,
                  note->holder != nullptr ? " (" : "", note->holder != nullptr ? note->holder : "",
                  note->holder != nullptr ? ")" : "");
    refusal_log_.line(now_s, line);
  }
}

void UdpAliengoAdapter::answer(const sockaddr_in& sender) {
  std::uint8_t frame[kHighStateBytes];
  encode_high_state(make_feedback(newest_.state, newest_.aliengo_mode, newest_.aliengo_frame), frame);
  const ssize_t sent =
      ::sendto(socket_, frame, sizeof frame, 0, reinterpret_cast<const sockaddr*>(&sender), sizeof sender);
  (sent == static_cast<ssize_t>(sizeof frame) ? counts_.states_sent : counts_.send_errors).add();
}

void UdpAliengoAdapter::log_once_per_second() {
  const double now_s = wall_seconds();
  refusal_log_.tick(now_s);
  if (now_s < next_count_log_s_) return;
  next_count_log_s_ = now_s + 1.0;
  const AlienGoCounters c = counters();
  const std::uint64_t drops = c.wrong_length + c.bad_crc + c.low_level + c.non_finite;
  if (drops != logged_drops_) {
    std::fprintf(log_,
                 "aliengo: HighCmd datagrams dropped so far: %llu wrong length, %llu bad CRC, %llu not high level, "
                 "%llu with NaN/Inf\n",
                 static_cast<unsigned long long>(c.wrong_length), static_cast<unsigned long long>(c.bad_crc),
                 static_cast<unsigned long long>(c.low_level), static_cast<unsigned long long>(c.non_finite));
    logged_drops_ = drops;
  }
  if (c.refused_not_holder != logged_not_holder_) {
    std::fprintf(log_,
                 "aliengo: %llu HighCmd refused in the last second: the CyberDog2 LCM client holds the robot "
                 "(until it is silent for 0.5 s)\n",
                 static_cast<unsigned long long>(c.refused_not_holder - logged_not_holder_));
    logged_not_holder_ = c.refused_not_holder;
  }
  if (c.ring_overflow != logged_overflow_) {
    std::fprintf(log_,
                 "aliengo: %llu HighCmd dropped in the last second: they arrive faster than the loop takes them "
                 "(%d a tick)\n",
                 static_cast<unsigned long long>(c.ring_overflow - logged_overflow_),
                 static_cast<int>(kCommandsPerSourcePerTick));
    logged_overflow_ = c.ring_overflow;
  }
  if (c.timeouts != logged_timeouts_) {
    std::fprintf(log_,
                 "aliengo: no HighCmd for 0.5 s from the client holding the robot: get-down protection "
                 "(PureDamper, or Off when Off); %llu times so far\n",
                 static_cast<unsigned long long>(c.timeouts));
    logged_timeouts_ = c.timeouts;
  }
  std::fflush(log_);
}

AlienGoCounters UdpAliengoAdapter::counters() const {
  AlienGoCounters c = counts_;
  c.illegal_moves = inbox_.counters().illegal_moves.load();
  c.refused_not_holder = client_.counters().refused_not_holder.load();
  c.timeouts = client_.counters().timeouts.load();
  c.ring_overflow = inbox_.counters().ring_overflow.load();
  return c;
}

void UdpAliengoAdapter::finish(std::FILE* out) {
  thread_.stop();
  log_refusals(wall_seconds());
  const AlienGoCounters c = counters();
  using ull = unsigned long long;
  std::fprintf(out,
               "aliengo: HighCmd %llu received, %llu accepted, %llu wrong length, %llu bad CRC, %llu not high "
               "level, %llu NaN/Inf, %llu illegal moves, %llu refused (another client held the robot), "
               "%llu faster than the loop takes them; %llu timeouts; HighState %llu sent, %llu send errors\n",
               ull(c.received), ull(c.accepted), ull(c.wrong_length), ull(c.bad_crc), ull(c.low_level),
               ull(c.non_finite), ull(c.illegal_moves), ull(c.refused_not_holder), ull(c.ring_overflow),
               ull(c.timeouts), ull(c.states_sent), ull(c.send_errors));
  std::fflush(out);
}

}  // namespace cerebellum
