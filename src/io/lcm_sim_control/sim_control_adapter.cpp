#include "io/lcm_sim_control/sim_control_adapter.hpp"

#include <lcm/lcm-cpp.hpp>

#include "io/common/wall_clock.hpp"
#include "io/lcm_common/lcm_packet.hpp"
#include "io/lcm_common/lcm_url.hpp"
#include "io/lcm_sim_control/sim_command_text.hpp"
#include "sim_command_lcmt.hpp"
#include "sim_command_result_lcmt.hpp"

namespace cerebellum {
namespace {

constexpr const char* kInterfaceName = "sim_command";
constexpr int kLinesPerSecond = 5;
// fingerprint, request id, string length, the longest accepted text and its nul
constexpr std::size_t kPacketMaxBytes = 8 + 8 + 4 + kSimCommandTextMaxBytes + 1;

}  // namespace

SimControlAdapter::SimControlAdapter(Simulation* simulation, FaultInjectingBackend* faults, LinkFaultSet* links,
                                     const std::string& url, std::FILE* log)
    : simulation_(simulation),
      faults_(faults),
      links_(links),
      log_(log),
      lcm_(open_lcm_url(url, kInterfaceName)),
      log_lines_(log, kInterfaceName, "sim_command results", kLinesPerSecond) {
  lcm_->subscribe(kSimCommandChannel, &SimControlAdapter::on_command, this);
  thread_.start([this] { step(); });
}

SimControlAdapter::~SimControlAdapter() { thread_.stop(); }

SimControlCounters SimControlAdapter::counters() const { return counts_; }

void SimControlAdapter::step() {
  handle_pending(*lcm_, 5);
  log_lines_.tick(wall_seconds());
}

void SimControlAdapter::on_command(const lcm::ReceiveBuffer* buffer, const std::string&) {
  const auto refuse_malformed = [&](const std::string& why) {
    counts_.malformed.add();
    log_lines_.line(wall_seconds(), "refused a " + std::to_string(buffer->data_size) + "-byte packet: " + why);
  };
  if (!has_fingerprint(buffer->data, buffer->data_size, sim_command_lcmt::getHash())) {
    refuse_malformed(to_string(WireDecode::WrongFingerprint));
    return;
  }
  if (buffer->data_size > kPacketMaxBytes) {
    refuse_malformed(std::string(to_string(WireDecode::Oversized)) + " (at most " + std::to_string(kPacketMaxBytes) +
                     " bytes)");
    return;
  }
  sim_command_lcmt message;
  const int size = static_cast<int>(buffer->data_size);
  if (message.decode(buffer->data, 0, size) != size) {
    refuse_malformed(to_string(WireDecode::Truncated));
    return;
  }
  const SimCommand command = parse_sim_command(message.command);
  const auto refuse = [&](const std::string& why) {
    counts_.refused.add();
    log_lines_.line(wall_seconds(), "refused: " + why);
    answer(message.request_id, false, why);
  };
  if (simulation_ == nullptr) {
    return refuse("this MC drives a real robot, not a simulation: push and fault act only on `cerebellum sim`");
  }
  if (command.link) {
    if (links_ == nullptr) return refuse("this simulation has no client link faults");
    links_->of(command.link->link).apply(*command.link);
    counts_.taken.add();
    const std::string done = "taken: " + fault_command_text(*command.link);
    log_lines_.line(wall_seconds(), done);
    answer(message.request_id, true, done);
    return;
  }
  if (command.fault) {
    if (faults_ == nullptr) return refuse("this robot has no fault injector");
    if (const std::string why = faults_->request(*command.fault); !why.empty()) return refuse(why);
    counts_.taken.add();
    const std::string done = "taken: " + fault_command_text(*command.fault);
    log_lines_.line(wall_seconds(), done);
    answer(message.request_id, true, done);
    return;
  }
  if (!command.push) return refuse(command.error);
  simulation_->request_force_pulse(*command.push);
  counts_.taken.add();
  const std::string done = "taken: " + push_command_text(*command.push) + " (N, N, N, s) on the trunk";
  log_lines_.line(wall_seconds(), done);
  answer(message.request_id, true, done);
}

void SimControlAdapter::answer(std::int64_t request_id, bool taken, const std::string& reason) {
  sim_command_result_lcmt result;
  result.request_id = request_id;
  result.result = taken ? 0 : 1;
  result.reason = reason;
  lcm_->publish(kSimCommandResultChannel, &result);
}

void SimControlAdapter::finish(std::FILE* out) {
  thread_.stop();
  if (finished_) return;
  finished_ = true;
  const SimControlCounters c = counters();
  std::fprintf(out, "sim_command: %llu taken, %llu refused, %llu malformed packets\n",
               static_cast<unsigned long long>(c.taken), static_cast<unsigned long long>(c.refused),
               static_cast<unsigned long long>(c.malformed));
}

}  // namespace cerebellum
