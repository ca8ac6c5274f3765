#include "custom_interface.hpp"

#include <lcm/lcm-cpp.hpp>
#include <poll.h>
#include <sys/timerfd.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#include "core/joint_layout.hpp"
#include "motor_ctrl_lcmt.hpp"
#include "motor_ctrl_state_lcmt.hpp"
#include "spi_data_t.hpp"
#include "state_estimator_lcmt.hpp"

namespace {

constexpr const char* kControlUrl = "udpm://239.255.76.67:7667?ttl=255";
constexpr const char* kEstimatorUrl = "udpm://239.255.76.67:7669?ttl=255";
constexpr double kDefaultLoopRateHz = 500.0;
constexpr int16_t kErrCommandLost = 0x02;
constexpr uint32_t kMotorErrorMask = 0x3FFFFFFF;  // everything but the mode bits

float wire_sign(std::size_t index) {
  return static_cast<float>(cerebellum::wire_sign(index % cerebellum::kJointsPerLeg));
}

RobotData initial_robot_data() {
  RobotData data;
  std::memset(&data, 0, sizeof(data));
  data.quat[0] = 1.0f;
  data.err_flag = kErrCommandLost;  // until the MC says otherwise: send activation frames
  return data;
}

}  // namespace

// the LCM side: one thread receives feedback into a buffer; Tick copies it and sends commands
class CustomInterface::Channels {
 public:
  Channels() : control_(kControlUrl), estimator_(kEstimatorUrl), received_(initial_robot_data()) {
    if (!control_.good() || !estimator_.good()) {
      throw std::runtime_error("cyber_dog_motor_sdk: cannot open LCM (" + std::string(kControlUrl) + ", " +
                               kEstimatorUrl + ")");
    }
    control_.subscribe("spi_data", &Channels::on_spi_data, this);
    control_.subscribe("motor_ctrl_state", &Channels::on_motor_ctrl_state, this);
    estimator_.subscribe("state_estimator", &Channels::on_state_estimator, this);
  }

  void start() {
    receiving_.store(true);
    receiver_ = std::thread([this] { receive(); });
  }

  void stop() {
    receiving_.store(false);
    if (receiver_.joinable()) receiver_.join();
  }

  void copy_feedback(RobotData& data) {
    std::lock_guard<std::mutex> lock(mutex_);
    data = received_;
  }

  void send(const MotorCmd& cmd) {
    motor_ctrl_lcmt message;
    for (std::size_t i = 0; i < 12; ++i) {
      const float sign = wire_sign(i);
      message.q_des[i] = sign * cmd.q_des[i];
      message.qd_des[i] = sign * cmd.qd_des[i];
      message.kp_des[i] = cmd.kp_des[i];
      message.kd_des[i] = cmd.kd_des[i];
      message.tau_des[i] = sign * cmd.tau_des[i];
    }
    control_.publish("motor_ctrl", &message);
  }

 private:
  void receive() {
    pollfd fds[2] = {{control_.getFileno(), POLLIN, 0}, {estimator_.getFileno(), POLLIN, 0}};
    while (receiving_.load()) {
      if (poll(fds, 2, 20) <= 0) continue;
      if (fds[0].revents & POLLIN) control_.handle();
      if (fds[1].revents & POLLIN) estimator_.handle();
    }
  }

  void on_spi_data(const lcm::ReceiveBuffer*, const std::string&, const spi_data_t* msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (std::size_t leg = 0; leg < 4; ++leg) {
      const float* q[3] = {msg->q_abad, msg->q_hip, msg->q_knee};
      const float* qd[3] = {msg->qd_abad, msg->qd_hip, msg->qd_knee};
      const float* tau[3] = {msg->tau_abad, msg->tau_hip, msg->tau_knee};
      for (std::size_t joint = 0; joint < 3; ++joint) {
        const std::size_t i = 3 * leg + joint;
        received_.q[i] = wire_sign(i) * q[joint][leg];
        received_.qd[i] = wire_sign(i) * qd[joint][leg];
        received_.tau[i] = wire_sign(i) * tau[joint][leg];
      }
    }
    for (std::size_t i = 0; i < 12; ++i) received_.motor_flags[i] = static_cast<uint32_t>(msg->flags[i]);
  }

  void on_motor_ctrl_state(const lcm::ReceiveBuffer*, const std::string&, const motor_ctrl_state_lcmt* msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    received_.err_flag = msg->err_flag;
    received_.ctrl_topic_interval = msg->ctrl_topic_interval;
  }

  void on_state_estimator(const lcm::ReceiveBuffer*, const std::string&, const state_estimator_lcmt* msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::memcpy(received_.quat, msg->quat, sizeof(received_.quat));
    std::memcpy(received_.rpy, msg->rpy, sizeof(received_.rpy));
    std::memcpy(received_.acc, msg->aWorld, sizeof(received_.acc));
    std::memcpy(received_.omega, msg->omegaWorld, sizeof(received_.omega));
  }

  lcm::LCM control_;
  lcm::LCM estimator_;
  std::mutex mutex_;
  RobotData received_;
  std::atomic<bool> receiving_{false};
  std::thread receiver_;
};

CustomInterface::CustomInterface(const double& loop_rate)
    : robot_data_(initial_robot_data()),
      loop_rate_hz_(loop_rate > 0.0 ? loop_rate : kDefaultLoopRateHz),
      channels_(new Channels()) {
  Zero_Cmd(motor_cmd_);
}

CustomInterface::~CustomInterface() { channels_->stop(); }

void CustomInterface::Spin() {
  const int timer = timerfd_create(CLOCK_MONOTONIC, TFD_CLOEXEC);
  if (timer < 0) throw std::runtime_error(std::string("cyber_dog_motor_sdk: timerfd_create: ") + std::strerror(errno));
  const long period_ns = std::lround(1e9 / loop_rate_hz_);
  itimerspec spec{};
  spec.it_interval.tv_sec = period_ns / 1000000000L;
  spec.it_interval.tv_nsec = period_ns % 1000000000L;
  spec.it_value = spec.it_interval;
  timerfd_settime(timer, 0, &spec, nullptr);
  channels_->start();
  while (!stop_requested_.load()) {
    uint64_t expirations = 0;
    if (read(timer, &expirations, sizeof(expirations)) != static_cast<ssize_t>(sizeof(expirations))) continue;
    Tick();
  }
  channels_->stop();
  close(timer);
}

void CustomInterface::Stop() { stop_requested_.store(true); }

void CustomInterface::Tick() {
  channels_->copy_feedback(robot_data_);
  UserCode(first_run_);
  // while the MC reports communication lost, only all-zero frames go out (they activate it)
  if (robot_data_.err_flag & kErrCommandLost) {
    Zero_Cmd(motor_cmd_);
    first_run_ = true;
  } else {
    first_run_ = false;
  }
  for (int i = 0; i < 12; ++i) {
    if (robot_data_.motor_flags[i] & kMotorErrorMask) {
      std::fprintf(stderr, "cyber_dog_motor_sdk: motor %d reports error flags 0x%08x; stopping\n", i,
                   static_cast<unsigned>(robot_data_.motor_flags[i]));
      Stop();
      return;
    }
  }
  channels_->send(motor_cmd_);
}

void CustomInterface::Zero_Cmd(MotorCmd& cmd) { std::memset(&cmd, 0, sizeof(cmd)); }

void CustomInterface::PrintData(RobotData& data) {
  auto print_row = [](const char* name, const float* values, int count) {
    std::printf("%-6s", name);
    for (int i = 0; i < count; ++i) std::printf(" %+8.3f", values[i]);
    std::printf("\n");
  };
  std::printf("err_flag 0x%02x  ctrl_topic_interval %.1f ms\n", static_cast<unsigned>(data.err_flag),
              data.ctrl_topic_interval);
  print_row("q", data.q, 12);
  print_row("qd", data.qd, 12);
  print_row("tau", data.tau, 12);
  print_row("quat", data.quat, 4);
  print_row("rpy", data.rpy, 3);
  print_row("acc", data.acc, 3);
  print_row("omega", data.omega, 3);
  std::printf("flags ");
  for (int i = 0; i < 12; ++i) std::printf(" %08x", static_cast<unsigned>(data.motor_flags[i]));
  std::printf("\n");
  std::fflush(stdout);
}
