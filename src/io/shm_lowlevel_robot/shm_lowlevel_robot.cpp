#include "io/shm_lowlevel_robot/shm_lowlevel_robot.hpp"

#include <chrono>
#include <cstddef>
#include <thread>

#include "io/common/wall_clock.hpp"
#include "io/robot_link/robot_link_log.hpp"
#include "io/shm_lowlevel/shm_codec.hpp"
#include "io/shm_lowlevel/shm_flags.hpp"
#include "io/shm_lowlevel/shm_lowlevel_config.hpp"
#include "safety/damping_command.hpp"

namespace cerebellum {
namespace {

constexpr RobotLinkWords kLinkWords{"zsibot", "joint state or IMU from the daemon", "state.legs"};
// the loop thread takes the state at least every millisecond (each substep): a longer gap is a
// pause of its own (descheduled, the machine stalled), after which the link watch starts again
constexpr double kListeningPauseS = 0.005;
constexpr int kLinkLinesPerSecond = 4;
// the daemon's cycle: a frame goes out again when the last one is this old
constexpr double kDaemonPeriodS = 0.001;
// the log thread's nap between looks at the statuses (the loop pushes one each 2 ms tick)
constexpr auto kLogNap = std::chrono::milliseconds(5);

}  // namespace

ShmLowLevelRobot::ShmLowLevelRobot(const ShmRobotConfig& config, std::FILE* log)
    : config_(config),
      log_(log),
      watch_(config.link_timeout_s),
      listening_(kListeningPauseS),
      link_log_(log, kLinkWords.robot, "link events", kLinkLinesPerSecond) {
  thread_.start([this] {
    log_step();
    std::this_thread::sleep_for(kLogNap);
  }, [this] { log_step(); });
}

ShmLowLevelRobot::~ShmLowLevelRobot() { thread_.stop(); }

bool ShmLowLevelRobot::map_objects() {
  if (spline_ && imu_) return true;
  const std::string spline_name = shm_spline_object_name(config_.name_prefix);
  const std::string imu_name = shm_imu_object_name(config_.name_prefix);
  if (!spline_) spline_ = ShmMapping::open_existing(spline_name, sizeof(spline_data_t), not_mapped_why_);
  if (spline_ && !imu_) imu_ = ShmMapping::open_existing(imu_name, sizeof(nav_imu_t), not_mapped_why_);
  return spline_ && imu_;
}

void ShmLowLevelRobot::take_state() {
  if (!spline_ || !imu_) return;
  const double now_s = wall_seconds();
  listening_.step(now_s);
  // the round trip: has the daemon taken the frame being timed (its flag cleared)?
  if (timed_frame_sent_s_ >= 0.0 && !timed_frame_taken_ && !lowlevel_command_pending(spline())) {
    timed_frame_taken_ = true;
  }
  // the SDK's fenced read (lowlevel_sync.h): a flag still set and the IMU's timestamp unchanged
  // after the copy is one whole frame; a flag that was set and a read that fails is a copy the
  // daemon rewrote under it
  const bool flagged = shm_state_flag(spline(), CONSUMER_CONTROL).load(std::memory_order_acquire) != 0;
  if (!flagged) return;
  leg_state_t legs[kNumLegs];
  nav_imu_t imu_frame;
  if (lowlevel_read_state(spline(), imu(), CONSUMER_CONTROL, legs, &imu_frame) == 0) {
    ++counts_.torn_states;
    return;
  }
  ++counts_.states_taken;
  // a state seen at or after the poll that found the frame taken: the daemon's answer to it (to
  // the poll's millisecond)
  if (timed_frame_taken_) {
    round_trip_s_ = now_s - timed_frame_sent_s_;
    ++round_trips_;
    timed_frame_sent_s_ = -1.0;
    timed_frame_taken_ = false;
  }
  watch_.take_joints(decode_shm_legs(legs), now_s);
  if (!have_imu_timestamp_ || imu_frame.timestamp != imu_timestamp_) {
    watch_.take_imu(decode_shm_imu(imu_frame), now_s);
    imu_timestamp_ = imu_frame.timestamp;
    have_imu_timestamp_ = true;
  }
}

void ShmLowLevelRobot::send_frame() {
  if (!spline_ || !have_command_) return;
  leg_control_t legs[kNumLegs];
  encode_shm_command(command_, legs);
  // the SDK's fenced write: nothing written while the daemon has not taken the last frame
  if (lowlevel_write_command(spline(), legs) == 0) {
    ++counts_.frames_waiting;
    // the frame went out a cycle ago and is still there: the daemon skipped a cycle
    if (++waits_in_row_ == 2) ++counts_.frames_late;
    return;
  }
  waits_in_row_ = 0;
  ++counts_.frames_written;
  if (timed_frame_sent_s_ < 0.0) {  // one frame timed at a time
    timed_frame_sent_s_ = wall_seconds();
    timed_frame_taken_ = false;
  }
  sent_at_s_ = robot_time_s_;
}

RobotLinkReport ShmLowLevelRobot::link_report() const {
  const RobotLinkStatus& s = watch_.status();
  return RobotLinkReport{true, s.link_silent_s, s.link_losses, s.repeated_states + s.jumped_states,
                         counts_.frames_late, round_trip_s_, round_trips_};
}

SensorFrame ShmLowLevelRobot::read() {
  take_state();
  const SensorFrame frame = watch_.frame(listening_.window(), robot_time_s_);
  statuses_.try_push(StatusAt{watch_.status(), robot_time_s_});
  return frame;
}

void ShmLowLevelRobot::write(const JointCommand& command) {
  // after a motor error the client stops for good: damping, holding nothing, until restart
  if (watch_.status().stopped) {
    command_ = damping_command(config_.motor_error_damping_kd, watch_.q());
    ++counts_.damping_frames;
  } else {
    command_ = command;
  }
  have_command_ = true;
  send_frame();
}

void ShmLowLevelRobot::advance(double period_s) {
  take_state();
  if (robot_time_s_ - sent_at_s_ >= kDaemonPeriodS - 1e-9) send_frame();
  robot_time_s_ += period_s;
}

bool ShmLowLevelRobot::activate(const std::atomic<bool>& stop) {
  const double deadline_s = wall_seconds() + config_.activation_timeout_s;
  const auto period = std::chrono::duration<double>(kDaemonPeriodS);
  bool announced = false;
  while (!stop.load(std::memory_order_relaxed) && wall_seconds() < deadline_s) {
    if (map_objects()) {
      if (!announced) {
        std::fprintf(log_, "zsibot: mapped %s and %s; waiting for the daemon's state\n", spline_->name().c_str(),
                     imu_->name().c_str());
        std::fflush(log_);
        announced = true;
      }
      read();
      if (!watch_.status().link_lost) return true;
    }
    std::this_thread::sleep_for(period);
  }
  if (spline_ && imu_) {
    not_mapped_why_ = "the daemon's state did not update (state.consumer_flags[CONSUMER_CONTROL] stayed 0, or the "
                      "IMU's timestamp did not move)";
  }
  return false;
}

std::string ShmLowLevelRobot::activation_text() const {
  char text[320];
  std::snprintf(text, sizeof text, "the ZsiBot's daemon at %s and %s (its state updating, up to %g s)",
                shm_spline_object_name(config_.name_prefix).c_str(), shm_imu_object_name(config_.name_prefix).c_str(),
                config_.activation_timeout_s);
  return text;
}

std::string ShmLowLevelRobot::activation_failure() const {
  return "the daemon did not answer within " + std::to_string(config_.activation_timeout_s) +
         " s: " + not_mapped_why_ + " (is the vendor's daemon running, with low-level control allowed?)";
}

std::string ShmLowLevelRobot::description() const {
  return "ZsiBot through lowlevel.h (" + shm_spline_object_name(config_.name_prefix) + ", " +
         shm_imu_object_name(config_.name_prefix) + ")";
}

void ShmLowLevelRobot::log_step() {
  while (const std::optional<StatusAt> now = statuses_.try_pop()) {
    log_link_changes(logged_.status, now->status, now->robot_time_s, config_.link_timeout_s, kLinkWords,
                     wall_seconds(), link_log_, log_);
    logged_ = *now;
    std::fflush(log_);
  }
}

void ShmLowLevelRobot::finish(std::FILE* out) {
  thread_.stop();
  const RobotLinkStatus& s = watch_.status();
  using ull = unsigned long long;
  std::fprintf(out,
               "zsibot: %s; %llu link losses; %llu states taken, %llu torn (not taken), states %llu repeated, %llu "
               "jumped; %llu frames written, %llu waited for the daemon (%llu over a cycle), %llu damping frames after a motor error\n",
               s.stopped ? "stopped on a motor error" : "no motor error", ull(s.link_losses), ull(counts_.states_taken),
               ull(counts_.torn_states), ull(s.repeated_states), ull(s.jumped_states), ull(counts_.frames_written),
               ull(counts_.frames_waiting), ull(counts_.frames_late), ull(counts_.damping_frames));
  std::fflush(out);
}

}  // namespace cerebellum
