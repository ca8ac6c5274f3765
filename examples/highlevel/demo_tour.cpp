// The demo tour: drives the MC through its high-level LCM interface like a user program would:
// stand up, tilt the body, walk a 1 m square, turn on the spot, jump forward, a back flip (not in
// the short tour), lie down. One progress line per step; a closing report (steps done, distances
// from the MC's odometry, errors). Exit 0 only when every step succeeded.
//   cerebellum_demo_tour [--short]     (--short: a smaller square, for CI)
#include <cerebellum/highlevel_client.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace {

using cerebellum::HighLevelClient;
using cerebellum::HighLevelClientStatus;
using std::chrono::milliseconds;

constexpr double kPi = 3.14159265358979323846;

struct Pose2d {
  double x = 0, y = 0, yaw = 0;
};

Pose2d odometry(const HighLevelClient& client) {
  const auto odometry = client.latest_odometry();
  if (!odometry) return {};
  return {odometry->xyz[0], odometry->xyz[1], odometry->rpy[2]};
}

robot_control_cmd_lcmt command(int mode, int gait, double vx = 0, double yaw_rate = 0) {
  robot_control_cmd_lcmt c{};
  c.mode = static_cast<std::int8_t>(mode);
  c.gait_id = static_cast<std::int8_t>(gait);
  c.contact = 0x0F;
  c.vel_des[0] = static_cast<float>(vx);
  c.vel_des[2] = static_cast<float>(yaw_rate);
  c.step_height[0] = c.step_height[1] = 0.06f;  // swing height (0..0.06 m), as the vendor's example sends
  return c;
}

class Tour {
 public:
  explicit Tour(HighLevelClient& client) : client_(client) {}

  // a mode the MC must reach (order_process_bar >= 95)
  void reach(const std::string& what, const robot_control_cmd_lcmt& c, int seconds) {
    begin(what);
    HighLevelClientStatus status = client_.send(c);
    if (status == HighLevelClientStatus::Ok)
      status = client_.wait_for_mode(c.mode, c.gait_id, milliseconds(1000 * seconds));
    end(status == HighLevelClientStatus::Ok, cerebellum::to_string(status));
  }

  // a command held for a time; reports the distance and turn the odometry saw
  void hold(const std::string& what, const robot_control_cmd_lcmt& c, double seconds, double expect_m,
            double expect_turn_rad) {
    begin(what);
    const Pose2d start = odometry(client_);
    HighLevelClientStatus status = client_.send(c);
    // sample the odometry to add up the turn across +-pi
    double turn = 0;
    double last_yaw = start.yaw;
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < until) {
      std::this_thread::sleep_for(milliseconds(50));
      const double yaw = odometry(client_).yaw;
      turn += std::remainder(yaw - last_yaw, 2 * kPi);
      last_yaw = yaw;
    }
    const Pose2d stop = odometry(client_);
    const double distance = std::hypot(stop.x - start.x, stop.y - start.y);
    distance_m_ += distance;
    const auto response = client_.latest_response();
    const bool in_mode = response && response->mode == c.mode;
    // the MC ramps the yaw rate (3 rad/s^2): a step after a turn still turns by about 10 degrees
    const bool moved =
        std::abs(distance - expect_m) <= std::max(0.35 * expect_m, 0.15) &&
        std::abs(std::abs(turn) - std::abs(expect_turn_rad)) <= std::max(0.35 * std::abs(expect_turn_rad), 0.3);
    char detail[128];
    std::snprintf(detail, sizeof(detail), "%.2f m, %+.0f deg", distance, turn * 180 / kPi);
    end(status == HighLevelClientStatus::Ok && in_mode && moved, detail);
  }

  int report() const {
    std::printf("\ndemo report: %d of %d steps succeeded, %.2f m walked (MC odometry)\n", succeeded_, steps_,
                distance_m_);
    for (const std::string& e : errors_) std::printf("  error: %s\n", e.c_str());
    return succeeded_ == steps_ ? 0 : 1;
  }

 private:
  void begin(const std::string& what) {
    current_ = what;
    started_ = std::chrono::steady_clock::now();
    ++steps_;
  }
  void end(bool ok, const std::string& detail) {
    const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    std::printf("[%2d] %-34s %-4s %s (%.1f s)\n", steps_, current_.c_str(), ok ? "ok" : "FAIL", detail.c_str(), took);
    std::fflush(stdout);
    if (ok) {
      ++succeeded_;
    } else {
      errors_.push_back(current_ + ": " + detail);
    }
  }

  HighLevelClient& client_;
  std::string current_;
  std::chrono::steady_clock::time_point started_;
  int steps_ = 0;
  int succeeded_ = 0;
  double distance_m_ = 0;
  std::vector<std::string> errors_;
};

}  // namespace

int main(int argc, char** argv) {
  const bool short_tour = argc > 1 && std::strcmp(argv[1], "--short") == 0;
  HighLevelClient client;
  if (client.start() != HighLevelClientStatus::Ok) {
    std::fprintf(stderr, "demo: cannot open LCM: %s\n", client.last_error().c_str());
    return 2;
  }
  Tour tour(client);
  const double side_m = short_tour ? 0.5 : 1.0;
  const double speed = 0.4;
  tour.reach("stand up (recovery stand, 12)", command(12, 0), 15);

  // mode 21 gait 0 is incremental: each command moves the body from where the last one left it
  robot_control_cmd_lcmt tilt = command(21, 0);
  tilt.rpy_des[1] = -0.2f;  // look down (+pitch raises the head)
  tilt.rpy_des[2] = 0.2f;   // and to the left
  tour.reach("pose: head down 0.2, yaw 0.2 (21)", tilt, 10);
  robot_control_cmd_lcmt untilt = command(21, 0);
  untilt.rpy_des[1] = 0.2f;
  untilt.rpy_des[2] = -0.2f;
  tour.reach("pose: back to level (21)", untilt, 10);
  if (!short_tour) {
    tour.reach("shake right hand (motion 62/2)", command(62, 2), 20);
    // a motion hands over to pose control or a stand (reference), not to locomotion directly
    tour.reach("pose: level after the motion (21)", command(21, 0), 10);
    tour.reach("stand on the hind legs (64)", command(64, 0), 15);
    tour.reach("pose: level after the two-leg stand (21)", command(21, 0), 10);
  }

  tour.reach("locomotion stand (11, gait 1)", command(11, 1), 10);
  for (int side = 1; side <= 4; ++side) {
    tour.hold("square side " + std::to_string(side) + " (trot 27)", command(11, 27, speed), side_m / speed, side_m,
              0.0);
    tour.hold("turn left 90 deg", command(11, 27, 0.0, 1.0), kPi / 2, 0.0, kPi / 2);
  }
  if (!short_tour) tour.hold("turn on the spot, fast trot (10)", command(11, 10, 0.0, 2.0), kPi, 0.0, 2 * kPi);
  tour.reach("stop (11, gait 1)", command(11, 1), 10);
  // a jump starts from a still stand (the MC refuses it while the robot still turns): let the
  // stand settle first
  std::this_thread::sleep_for(milliseconds(1000));
  tour.reach("jump forward 30 cm (16, jump 4)", command(16, 4), 10);
  if (!short_tour) {
    // the flip too starts from a still stand: the jump's landing settles first
    std::this_thread::sleep_for(milliseconds(1000));
    tour.reach("back flip (16, jump 20)", command(16, 20), 10);
  }
  tour.reach("lie down (7, gait 1)", command(7, 1), 10);
  client.stop();
  return tour.report();
}
