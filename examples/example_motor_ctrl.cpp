// The motor SDK example: after activation, move every leg from where it is to the lying pose
// over 1500 ticks, then to the standing pose over 1500 ticks, and hold (kp 60, kd 2, 500 Hz).
//   example_motor_ctrl [run_seconds]   (default: until Ctrl-C)
#include <custom_interface.hpp>

#include <pthread.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <thread>

namespace {

constexpr double kLoopRateHz = 500.0;
constexpr double kTicksPerSegment = 1500.0;
constexpr float kDegToRad = 3.14159265f / 180.0f;
// per leg: abad, hip, knee (SDK convention)
constexpr float kLyingPose[3] = {0.0f * kDegToRad, 80.0f * kDegToRad, -135.0f * kDegToRad};
constexpr float kStandingPose[3] = {0.0f * kDegToRad, 45.0f * kDegToRad, -70.0f * kDegToRad};

class StandUpCtrl : public CustomInterface {
 public:
  StandUpCtrl(double loop_rate_hz, long long run_ticks) : CustomInterface(loop_rate_hz), run_ticks_(run_ticks) {}

 private:
  void UserCode(bool first_run) override {
    if (first_run) {
      // remember where the joints are; restart the motion once the feedback looks real (knees bent)
      for (int i = 0; i < 12; ++i) start_q_[i] = robot_data_.q[i];
      const bool knees_bent = start_q_[2] < -0.1f && start_q_[5] < -0.1f && start_q_[8] < -0.1f && start_q_[11] < -0.1f;
      if (knees_bent) motion_tick_ = 0;
    } else {
      const double s = static_cast<double>(motion_tick_) / kTicksPerSegment;
      const float t = static_cast<float>(s > 2.0 ? 2.0 : s);
      for (int i = 0; i < 12; ++i) {
        const int joint = i % 3;
        motor_cmd_.q_des[i] = t < 1.0f ? start_q_[i] * (1.0f - t) + kLyingPose[joint] * t
                                       : kLyingPose[joint] * (2.0f - t) + kStandingPose[joint] * (t - 1.0f);
        motor_cmd_.qd_des[i] = 0.0f;
        motor_cmd_.kp_des[i] = 60.0f;
        motor_cmd_.kd_des[i] = 2.0f;
        motor_cmd_.tau_des[i] = 0.0f;
      }
      ++motion_tick_;
    }
    if (total_tick_ % 1000 == 0) PrintData(robot_data_);
    ++total_tick_;
    if (run_ticks_ > 0 && total_tick_ >= run_ticks_) {
      std::printf("example_motor_ctrl: done after %lld ticks, err_flag 0x%02x\n", total_tick_,
                  static_cast<unsigned>(robot_data_.err_flag));
      Stop();
    }
  }

  long long run_ticks_;
  long long total_tick_ = 0;
  long long motion_tick_ = 0;
  float start_q_[12] = {};
};

}  // namespace

int main(int argc, char** argv) {
  double run_seconds = 0.0;
  if (argc > 2 || (argc == 2 && (run_seconds = std::atof(argv[1])) <= 0.0)) {
    std::fprintf(stderr, "usage: example_motor_ctrl [run_seconds > 0]   (default: until Ctrl-C)\n");
    return 2;
  }
  // Ctrl-C / SIGTERM are blocked in every thread and picked up by a watcher that stops the loop
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  StandUpCtrl controller(kLoopRateHz, static_cast<long long>(run_seconds * kLoopRateHz));
  std::atomic<bool> finished{false};
  std::thread watcher([&] {
    const timespec poll_period{0, 100000000};
    while (!finished.load()) {
      if (sigtimedwait(&stop_signals, nullptr, &poll_period) > 0) {
        controller.Stop();
        return;
      }
    }
  });
  controller.Spin();
  finished.store(true);
  watcher.join();
  return 0;
}
