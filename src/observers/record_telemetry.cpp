#include "observers/record_telemetry.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "observers/viewer_snapshot.hpp"
#include "core/orientation.hpp"

namespace cerebellum {
namespace {

// the CSV columns name legs in lower case
constexpr const char* kLegColumnNames[kNumLegs] = {"fr", "fl", "rr", "rl"};

void append_number(std::string& line, double value) {
  char text[32];
  std::snprintf(text, sizeof text, ",%.6g", value);
  line += text;
}

}  // namespace

TelemetryRow telemetry_row(const CycleRecord& record, const GroundTruth& truth) {
  const RobotState& state = record.state;
  const HighLevelStatus& status = record.high_level.status;
  const HighLevelCommand& running = record.high_level.running_command;
  TelemetryRow row;
  row.time_s = state.time_s;
  row.tick = record.tick;
  row.mode = status.mode;
  row.gait_id = status.gait_id;
  row.switch_status = static_cast<int>(status.switch_status);
  if (running.mode == static_cast<int>(ModeId::Locomotion)) {
    row.cmd_velocity = {running.vel_des[0], running.vel_des[1], running.vel_des[2]};
  }
  row.est_velocity = {state.velocity_body.x(), state.velocity_body.y(), state.omega_body.z()};
  row.est_height_m = state.height_m;
  row.est_rpy = {state.rpy.x(), state.rpy.y(), state.rpy.z()};
  row.truth_velocity = planar_velocity_body(truth.quat, truth.velocity_world, truth.angular_velocity_body);
  row.truth_z_m = truth.position[2];
  const Eigen::Vector3d truth_rpy =
      rpy_from_quaternion(Eigen::Quaterniond(truth.quat[0], truth.quat[1], truth.quat[2], truth.quat[3]));
  row.truth_rpy = {truth_rpy.x(), truth_rpy.y(), truth_rpy.z()};
  row.tau_nm = state.tau;
  row.temperature_c = state.temperature_c;
  row.battery_soc_percent = state.battery.state_of_charge_percent;
  row.battery_v = state.battery.voltage_v;
  row.battery_a = state.battery.current_a;
  row.health_causes = record.health.causes;
  row.faulty_motors = record.health.faulty_motors;
  return row;
}

std::string telemetry_header() {
  std::string header =
      "time_s,tick,mode,gait_id,switch_status,cmd_vx_m_s,cmd_vy_m_s,cmd_wz_rad_s,"
      "est_vx_m_s,est_vy_m_s,est_wz_rad_s,est_height_m,est_roll_rad,est_pitch_rad,est_yaw_rad,"
      "truth_vx_m_s,truth_vy_m_s,truth_wz_rad_s,truth_z_m,truth_roll_rad,truth_pitch_rad,truth_yaw_rad";
  for (const char* quantity : {"tau", "temp"}) {
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      for (std::size_t joint = 0; joint < kJointsPerLeg; ++joint) {
        header += std::string(",") + quantity + "_" + kLegColumnNames[leg] + "_" + kJointNames[joint] +
                  (std::strcmp(quantity, "tau") == 0 ? "_nm" : "_c");
      }
    }
  }
  header += ",battery_soc_percent,battery_v,battery_a,health_causes,faulty_motors";
  return header;
}

std::string telemetry_line(const TelemetryRow& row) {
  char head[96];
  std::snprintf(head, sizeof head, "%.4f,%llu,%d,%d,%d", row.time_s, static_cast<unsigned long long>(row.tick),
                row.mode, row.gait_id, row.switch_status);
  std::string line = head;
  for (double v : row.cmd_velocity) append_number(line, v);
  for (double v : row.est_velocity) append_number(line, v);
  append_number(line, row.est_height_m);
  for (double v : row.est_rpy) append_number(line, v);
  for (double v : row.truth_velocity) append_number(line, v);
  append_number(line, row.truth_z_m);
  for (double v : row.truth_rpy) append_number(line, v);
  for (double v : row.tau_nm) append_number(line, v);
  for (double v : row.temperature_c) append_number(line, v);
  append_number(line, row.battery_soc_percent);
  append_number(line, row.battery_v);
  append_number(line, row.battery_a);
  for (std::uint32_t bits : {row.health_causes, row.faulty_motors}) {
    line += ',';
    line += std::to_string(bits);
  }
  return line;
}

TelemetryRecorder::TelemetryRecorder(const std::string& path, double rate_hz, const Simulation& simulation)
    : path_(path), rate_hz_(rate_hz), simulation_(simulation) {
  if (!(rate_hz > 0.0)) throw std::invalid_argument("telemetry: the rate must be > 0 Hz");
  file_ = std::fopen(path.c_str(), "w");
  if (!file_) throw std::runtime_error("telemetry: cannot create " + path + ": " + std::strerror(errno));
  std::fprintf(file_, "%s\n", telemetry_header().c_str());
  writer_ = std::thread([this] { drain(); });
}

TelemetryRecorder::~TelemetryRecorder() { finish(); }

void TelemetryRecorder::on_cycle(const CycleRecord& record) {
  const double time_s = simulation_.time_s();
  if (!started_) {
    started_ = true;
    start_s_ = time_s;
  }
  if (time_s < start_s_ + static_cast<double>(next_row_) / rate_hz_ - 1e-9) return;
  // one row per tick at most: a rate above the loop's gives every tick
  while (time_s >= start_s_ + static_cast<double>(next_row_) / rate_hz_ - 1e-9) ++next_row_;
  ring_.try_push(telemetry_row(record, simulation_.ground_truth()));
}

void TelemetryRecorder::drain() {
  const auto write_queued = [this] {
    bool any = false;
    while (auto row = ring_.try_pop()) {
      any = true;
      const std::string line = telemetry_line(*row);
      if (std::fprintf(file_, "%s\n", line.c_str()) < 0) write_error_ = true;
      ++rows_written_;
    }
    return any;
  };
  while (running_.load(std::memory_order_acquire)) {
    if (!write_queued()) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  write_queued();
}

TelemetryResult TelemetryRecorder::finish() {
  if (finished_) return result_;
  finished_ = true;
  running_.store(false, std::memory_order_release);
  writer_.join();
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  result_.rows = rows_written_;
  result_.dropped = ring_.dropped();
  result_.ok = closed && !write_error_ && result_.dropped == 0;
  return result_;
}

}  // namespace cerebellum
