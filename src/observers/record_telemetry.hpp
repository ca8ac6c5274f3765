// `cerebellum sim --telemetry FILE.csv`: one CSV row per 1/rate of robot time. The loop thread
// only copies a row into a ring; a writer thread formats and writes it. Columns: time, MC status
// and the commanded velocity (the cycle record's high-level report), the estimator's velocity /
// height / attitude, simulator truth of the same (columns named truth_*: tools only, never the
// controller's input), joint torques and temperatures.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <string>
#include <thread>

#include "backend/simulation.hpp"
#include "core/spsc_ring.hpp"
#include "cycle/cycle_observer.hpp"

namespace cerebellum {

struct TelemetryRow {
  double time_s = 0.0;
  std::uint64_t tick = 0;
  int mode = 0;
  int gait_id = 0;
  int switch_status = 0;
  std::array<double, 3> cmd_velocity{};  // what the client asked of mode 11 (0 in other modes)
  std::array<double, 3> est_velocity{};  // vx, vy (m/s, body frame), wz (rad/s)
  double est_height_m = 0.0;
  std::array<double, 3> est_rpy{};
  std::array<double, 3> truth_velocity{};  // same frames as est_velocity
  double truth_z_m = 0.0;                  // trunk height above the world origin
  std::array<double, 3> truth_rpy{};
  JointArray<double> tau_nm{};
  JointArray<double> temperature_c{};
  double battery_soc_percent = 0.0;  // as the battery reports it (0 without a battery)
  double battery_v = 0.0;
  double battery_a = 0.0;
  std::uint32_t health_causes = 0;  // HealthCause bits of the health protection
  std::uint32_t faulty_motors = 0;  // bit i: motor i reports an error or a warning
};

// the cycle (its state and high-level report) and the simulator's truth as one row
TelemetryRow telemetry_row(const CycleRecord& record, const GroundTruth& truth);
// the header line and one row, without the newline
std::string telemetry_header();
std::string telemetry_line(const TelemetryRow& row);

struct TelemetryResult {
  std::uint64_t rows = 0;
  std::uint64_t dropped = 0;  // rows lost because the writer fell behind
  bool ok = false;            // every row written and the file closed without error
};

class TelemetryRecorder final : public CycleObserver {
 public:
  // rate_hz: rows per second of robot time (a rate above the loop's gives every tick);
  // throws std::runtime_error naming the file when it cannot be created
  TelemetryRecorder(const std::string& path, double rate_hz, const Simulation& simulation);
  ~TelemetryRecorder() override;
  TelemetryRecorder(const TelemetryRecorder&) = delete;
  TelemetryRecorder& operator=(const TelemetryRecorder&) = delete;

  void on_cycle(const CycleRecord& record) override;
  // writes what is queued and closes the file; idempotent
  TelemetryResult finish();

 private:
  void drain();

  std::string path_;
  double rate_hz_;
  const Simulation& simulation_;
  std::FILE* file_ = nullptr;
  // loop thread
  bool started_ = false;
  double start_s_ = 0.0;
  std::uint64_t next_row_ = 0;
  SpscRing<TelemetryRow, 4096> ring_;
  std::atomic<bool> running_{true};
  std::uint64_t rows_written_ = 0;  // writer thread until joined
  bool write_error_ = false;
  bool finished_ = false;
  TelemetryResult result_;
  std::thread writer_;
};

}  // namespace cerebellum
