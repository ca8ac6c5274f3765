#include "io/lcm_motor_sdk_robot/lcm_motor_sdk_robot.hpp"

#include <lcm/lcm-cpp.hpp>

#include <cmath>
#include <thread>

#include "io/common/wall_clock.hpp"
#include "io/lcm_common/lcm_packet.hpp"
#include "io/lcm_common/lcm_url.hpp"
#include "io/lcm_motor_sdk/motor_sdk_wire.hpp"
#include "io/lcm_motor_sdk/robot_state_messages.hpp"
#include "io/robot_link/robot_link_log.hpp"

namespace cerebellum {
namespace {

constexpr const char* kInterfaceName = "cyberdog2 motor sdk robot";
// the vendor's client period: activation frames go out at this rate too
constexpr double kClientPeriodS = 0.002;
// the thread wakes at least every millisecond (handle_pending's wait): a longer gap between its
// steps is a pause of its own (descheduled, the machine stalled), after which the link watch
// starts again (listening_window.hpp)
constexpr double kListeningPauseS = 0.005;
// link events (lost, back) a flapping link can provoke: a few per second, the rest summed up
constexpr int kLinkLinesPerSecond = 4;
constexpr RobotLinkWords kLinkWords{"cyberdog2", "spi_data or state_estimator", "spi_data"};

template <typename Number, std::size_t N>
bool all_finite(const Number (&values)[N]) {
  for (const Number value : values) {
    if (!std::isfinite(value)) return false;
  }
  return true;
}

bool finite(const spi_data_t& m) {
  return all_finite(m.q_abad) && all_finite(m.q_hip) && all_finite(m.q_knee) && all_finite(m.qd_abad) &&
         all_finite(m.qd_hip) && all_finite(m.qd_knee) && all_finite(m.tau_abad) && all_finite(m.tau_hip) &&
         all_finite(m.tau_knee);
}

bool finite(const state_estimator_lcmt& m) {
  return all_finite(m.quat) && all_finite(m.omegaBody) && all_finite(m.aBody);
}

bool finite(const motor_ctrl_state_lcmt& m) { return std::isfinite(m.ctrl_topic_interval); }

// one packet from the robot: decoded (fingerprint, exact size), its values finite, then made into
// what the loop takes and handed over; each refusal counted
template <typename Message, typename Ring, typename Make>
void receive(const lcm::ReceiveBuffer* buffer, Ring& ring, MotorSdkRobotRejections& rejected, Make make) {
  Message message{};
  if (decode_fixed_size(buffer->data, buffer->data_size, message) != WireDecode::Ok) {
    rejected.malformed.add();
  } else if (!finite(message)) {
    rejected.non_finite.add();
  } else if (!ring.try_push(make(message))) {
    rejected.dropped.add();
  }
}

}  // namespace

LcmMotorSdkRobot::LcmMotorSdkRobot(const MotorSdkRobotConfig& config, std::FILE* log)
    : config_(config),
      log_(log),
      control_lcm_(open_lcm_url(config.control_url, kInterfaceName)),
      estimator_lcm_(open_lcm_url(config.estimator_url, kInterfaceName)),
      client_(config),
      listening_(kListeningPauseS),
      link_log_(log, "cyberdog2", "link events", kLinkLinesPerSecond),
      count_log_period_(wall_seconds()) {
  control_lcm_->subscribe(kSpiDataChannel, &LcmMotorSdkRobot::on_spi_data, this);
  control_lcm_->subscribe(kMotorCtrlStateChannel, &LcmMotorSdkRobot::on_ctrl_state, this);
  estimator_lcm_->subscribe(kStateEstimatorChannel, &LcmMotorSdkRobot::on_state_estimator, this);
  thread_.start([this] { step(); });
}

LcmMotorSdkRobot::~LcmMotorSdkRobot() { thread_.stop(); }

SensorFrame LcmMotorSdkRobot::read() {
  while (const std::optional<Joints> joints = joints_.try_pop()) client_.take_joints(joints->state, joints->received_s);
  while (const std::optional<Imu> imu = imu_.try_pop()) client_.take_imu(imu->sample, imu->received_s);
  while (const std::optional<std::uint16_t> err_flag = err_flags_.try_pop()) client_.take_err_flag(*err_flag);
  const SensorFrame frame = client_.frame(listening_.window(), robot_time_s_);
  statuses_.try_push(StatusAt{client_.status(), robot_time_s_});
  return frame;
}

RobotLinkReport LcmMotorSdkRobot::link_report() const {
  const MotorSdkClientStatus& s = client_.status();
  return RobotLinkReport{true, s.link_silent_s, s.link_losses, s.repeated_states + s.jumped_states, s.late_reports};
}

void LcmMotorSdkRobot::write(const JointCommand& command) {
  frames_.try_push(encode_motor_ctrl(client_.command(command)));
}

bool LcmMotorSdkRobot::activate(const std::atomic<bool>& stop) {
  const double deadline_s = wall_seconds() + config_.activation_timeout_s;
  const auto period = std::chrono::duration<double>(kClientPeriodS);
  while (!stop.load(std::memory_order_relaxed) && wall_seconds() < deadline_s) {
    write(passive_command());
    read();
    const MotorSdkClientStatus& status = client_.status();
    if (status.activated && !status.link_lost) return true;
    std::this_thread::sleep_for(period);
    advance(kClientPeriodS);
  }
  return false;
}

std::string LcmMotorSdkRobot::activation_text() const {
  char text[320];
  std::snprintf(text, sizeof text, "the CyberDog2's motor mode on %s (all-zero frames, up to %g s)",
                config_.control_url.c_str(), config_.activation_timeout_s);
  return text;
}

std::string LcmMotorSdkRobot::activation_failure() const {
  char text[512];
  std::snprintf(text, sizeof text,
                "the robot did not take our frames within %g s: no spi_data, state_estimator or motor_ctrl_state "
                "without err_flag bit 1 on %s / %s (is the vendor's MC in motor mode, on this network?)",
                config_.activation_timeout_s, config_.control_url.c_str(), config_.estimator_url.c_str());
  return text;
}

std::string LcmMotorSdkRobot::description() const {
  return "CyberDog2 through its motor SDK (" + config_.control_url + ")";
}

void LcmMotorSdkRobot::step() {
  listening_.step(wall_seconds());
  handle_pending(*control_lcm_, 1);
  handle_pending(*estimator_lcm_, 0);
  while (const std::optional<motor_ctrl_lcmt> frame = frames_.try_pop()) {
    control_lcm_->publish(kMotorCtrlChannel, &*frame);
  }
  while (const std::optional<StatusAt> status = statuses_.try_pop()) log_changes(*status);
  log_counts_once_per_second();
}

void LcmMotorSdkRobot::on_spi_data(const lcm::ReceiveBuffer* buffer, const std::string&) {
  receive<spi_data_t>(buffer, joints_, rejected_, [](const spi_data_t& message) {
    return Joints{joint_state_from_spi_data(message), wall_seconds()};
  });
}

void LcmMotorSdkRobot::on_state_estimator(const lcm::ReceiveBuffer* buffer, const std::string&) {
  receive<state_estimator_lcmt>(buffer, imu_, rejected_, [](const state_estimator_lcmt& message) {
    return Imu{imu_from_state_estimator(message), wall_seconds()};
  });
}

void LcmMotorSdkRobot::on_ctrl_state(const lcm::ReceiveBuffer* buffer, const std::string&) {
  receive<motor_ctrl_state_lcmt>(buffer, err_flags_, rejected_, [](const motor_ctrl_state_lcmt& message) {
    return static_cast<std::uint16_t>(message.err_flag);
  });
}

void LcmMotorSdkRobot::log_changes(const StatusAt& now) {
  const MotorSdkClientStatus& was = logged_.status;
  const MotorSdkClientStatus& is = now.status;
  char line[256];
  if (is.activated && !was.activated) {
    std::snprintf(line, sizeof line, "the robot takes our frames (err_flag 0x%02x) at %.3f s robot time",
                  static_cast<unsigned>(is.err_flag), now.robot_time_s);
    link_log_.line(wall_seconds(), line);
  } else if (!is.activated && was.activated) {
    std::snprintf(line, sizeof line,
                  "err_flag 0x%02x at %.3f s robot time: the robot lost our frames and damps; all-zero frames "
                  "until it takes them again",
                  static_cast<unsigned>(is.err_flag), now.robot_time_s);
    link_log_.line(wall_seconds(), line);
  }
  log_link_changes(was, is, now.robot_time_s, config_.link_timeout_s, kLinkWords, wall_seconds(), link_log_, log_);
  logged_ = now;
  std::fflush(log_);
}

void LcmMotorSdkRobot::log_counts_once_per_second() {
  if (!count_log_period_.due(wall_seconds())) return;
  const std::uint64_t total = rejected_.malformed + rejected_.non_finite + rejected_.dropped;
  if (total == counts_logged_) return;
  std::fprintf(log_, "cyberdog2: packets from the robot refused so far: %llu malformed, %llu with NaN/Inf, %llu "
               "dropped (the loop did not take them)\n",
               static_cast<unsigned long long>(rejected_.malformed.load()),
               static_cast<unsigned long long>(rejected_.non_finite.load()),
               static_cast<unsigned long long>(rejected_.dropped.load()));
  std::fflush(log_);
  counts_logged_ = total;
}

void LcmMotorSdkRobot::finish(std::FILE* out) {
  thread_.stop();
  const MotorSdkClientStatus& s = client_.status();
  using ull = unsigned long long;
  std::fprintf(out,
               "cyberdog2: err_flag 0x%02x, %s; %llu link losses; %llu all-zero frames; frames clamped: %llu to "
               "ranges, %llu position jumps; robot reported %llu late, %llu jumps; states %llu repeated, %llu "
               "jumped; refused %llu malformed, %llu non-finite, %llu dropped; %llu frames not sent (queue full)\n",
               static_cast<unsigned>(s.err_flag), s.stopped ? "stopped on a motor error" : "no motor error",
               ull(s.link_losses), ull(s.zero_frames), ull(s.range_clamps), ull(s.jump_clamps), ull(s.late_reports),
               ull(s.jump_reports), ull(s.repeated_states), ull(s.jumped_states), ull(rejected_.malformed.load()), ull(rejected_.non_finite.load()),
               ull(rejected_.dropped.load()), ull(frames_.dropped()));
  std::fflush(out);
}

}  // namespace cerebellum
