// How far toward a back flip the simulated 12 Nm body gets with this MC's jump controller (the
// measurement behind keeping the flip ids refused, docs/jumps.md): from a stand, the highest
// push the legs allow with the trunk asked to take off pitching nose-up at a range of rates; the
// pitch rotation reached from lift-off to the first touchdown, on the simulator's truth. A back
// flip needs a full turn (6.28 rad) before the feet come down. Not part of the MC: the flight
// is not landed (the robot comes down wherever it is).
//   flip_reach_bench [--rates=4,8,12,16]
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "loop/control_loop.hpp"
#include "backend/mujoco_backend.hpp"
#include "control/jump/jump_controller.hpp"
#include "estimation/body_state_estimator.hpp"
#include "modes/recovery_stand_mode.hpp"

namespace {

using namespace cerebellum;

// stands up, then flies the jump plan it is given
class FlipAttempt final : public MotionController {
 public:
  explicit FlipAttempt(const JumpPlan& plan) : recovery_(default_stand_up_config()), plan_(plan) {}
  void compute(const RobotState& state, JointCommand& command) override {
    if (!started_) {
      started_ = true;
      HighLevelCommand stand;
      stand.mode = static_cast<int>(ModeId::RecoveryStand);
      recovery_.enter(state, stand);
    }
    if (!jumping_ && state.time_s > 4.0) {
      jumping_ = true;
      jump_.start(state, plan_);
    }
    if (jumping_) {
      jump_.compute(state, command);
    } else {
      recovery_.run(state, command);
    }
  }
  const JumpController& jump() const { return jump_; }

 private:
  RecoveryStandMode recovery_;
  JumpController jump_;
  JumpPlan plan_;
  bool started_ = false;
  bool jumping_ = false;
};

struct Reach {
  double asked_rate = 0.0;
  double takeoff_rate = 0.0;  // pitch rate at lift-off (truth)
  double rotation = 0.0;      // pitch turned from lift-off to the first touchdown
  double flight_s = 0.0;
};

Reach attempt(double pitch_rate) {
  MujocoBackendConfig sim;
  sim.model_path = std::string(CEREBELLUM_MODEL_DIR) + "/cyberdog2.xml";
  MujocoBackend backend(sim);
  BodyStateEstimator estimator;
  // the highest hop the legs allow, taking off pitching nose-up (negative pitch rate)
  const JumpControllerConfig config = default_jump_controller_config();
  JumpTarget up;
  up.apex_rise_m = 1.0;
  JumpPlan plan = plan_jump(up, config.limits);
  plan.takeoff_tilt_rate_rad_s.y() = -pitch_rate;
  FlipAttempt flip(plan);
  ControlLoop loop(backend, estimator, flip, GuardLimits{}, 0.002);
  Reach reach;
  reach.asked_rate = pitch_rate;
  bool airborne = false;
  bool landed = false;
  while (backend.time_s() < 7.0 && !landed) {
    loop.tick();
    const GroundTruth g = backend.ground_truth();
    const bool any_contact = g.foot_contact[0] || g.foot_contact[1] || g.foot_contact[2] || g.foot_contact[3];
    const double pitch_rate_now = g.angular_velocity_body[1];
    if (flip.jump().phase() == JumpPhase::Flight || flip.jump().phase() == JumpPhase::Push) {
      if (!airborne && !any_contact && flip.jump().phase() == JumpPhase::Flight) {
        airborne = true;
        reach.takeoff_rate = pitch_rate_now;
      }
    }
    if (airborne) {
      // the trunk or a foot touching the ground ends the flight
      const bool trunk_down = g.position[2] < 0.12;
      if ((any_contact || trunk_down) && reach.flight_s > 0.05) {
        landed = true;
      } else {
        reach.rotation += pitch_rate_now * 0.002;
        reach.flight_s += 0.002;
      }
    }
  }
  return reach;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<double> rates{4.0, 8.0, 12.0, 16.0};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--rates=", 0) == 0) {
      rates.clear();
      std::size_t pos = 8;
      while (pos < arg.size()) {
        const std::size_t comma = arg.find(',', pos);
        rates.push_back(std::stod(arg.substr(pos, comma - pos)));
        pos = comma == std::string::npos ? arg.size() : comma + 1;
      }
    } else if (arg.rfind("--benchmark_", 0) != 0) {
      std::fprintf(stderr, "usage: flip_reach_bench [--rates=4,8,...]\n");
      return 2;
    }
  }
  std::printf(
      "| asked take-off pitch rate (rad/s) | reached at lift-off (rad/s) | flight (s) | rotation before touchdown "
      "(rad) | of a back flip |\n");
  std::printf("|---|---|---|---|---|\n");
  for (const double rate : rates) {
    const Reach r = attempt(rate);
    std::printf("| %.1f | %.2f | %.3f | %.2f | %.0f %% |\n", r.asked_rate, -r.takeoff_rate, r.flight_s, -r.rotation,
                100.0 * -r.rotation / (2.0 * 3.14159265358979));
    std::fflush(stdout);
  }
  return 0;
}
