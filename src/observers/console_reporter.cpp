#include "observers/console_reporter.hpp"

#include <chrono>

#include "core/joint_layout.hpp"

namespace cerebellum {

ConsoleReporter::ConsoleReporter(std::FILE* out, double interval_s) : out_(out), interval_s_(interval_s) {
  printer_ = std::thread([this] {
    while (running_.load()) {
      drain();
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    drain();
  });
}

ConsoleReporter::~ConsoleReporter() { finish(); }

void ConsoleReporter::finish() {
  running_.store(false);
  if (printer_.joinable()) printer_.join();
}

void ConsoleReporter::on_cycle(const CycleRecord& record) {
  // one record per interval of robot time reaches the printer
  if (record.state.time_s + 1e-9 < next_print_s_) return;
  next_print_s_ = record.state.time_s + interval_s_;
  ring_.try_push(record);
}

void ConsoleReporter::drain() {
  while (auto record = ring_.try_pop()) print(*record);
  std::fflush(out_);
}

void ConsoleReporter::print(const CycleRecord& record) {
  const RobotState& s = record.state;
  std::fprintf(out_, "t=%7.2f s  height=%.3f m  rpy=(%+.2f %+.2f %+.2f)  guard=0x%02x", s.time_s, s.height_m, s.rpy.x(),
               s.rpy.y(), s.rpy.z(), record.safety.flags);
  if (s.battery.present) {
    std::fprintf(out_, "  battery=%.1f %% %.1f V", s.battery.state_of_charge_percent, s.battery.voltage_v);
  }
  if (record.health.protecting()) {
    std::fprintf(out_, "  PROTECTED (%s, causes 0x%02x, %.1f s)",
                 record.health.protection == Protection::Stopped ? "motors off" : "damping",
                 static_cast<unsigned>(record.health.causes), record.health.protected_s);
  }
  std::fputc('\n', out_);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    std::fprintf(out_,
                 "    %s q=(%+.3f %+.3f %+.3f) rad  qd=(%+6.2f %+6.2f %+6.2f) rad/s  tau=(%+5.2f %+5.2f %+5.2f) Nm\n",
                 kLegNames[leg], s.q[3 * leg], s.q[3 * leg + 1], s.q[3 * leg + 2], s.qd[3 * leg], s.qd[3 * leg + 1],
                 s.qd[3 * leg + 2], s.tau[3 * leg], s.tau[3 * leg + 1], s.tau[3 * leg + 2]);
  }
}

}  // namespace cerebellum
