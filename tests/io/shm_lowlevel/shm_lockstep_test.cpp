// The shared-memory interface in the MC, lockstep: the whole MC (simulated robot, state machine,
// arbiter, 1 ms loop) runs one tick at a time and the test acts as the client on the mapped
// memory between ticks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>

#include "loop/mc.hpp"
#include "loop/simulated_robot.hpp"
#include "io/shm_lowlevel/shm_lowlevel_port.hpp"
#include "io/shm_lowlevel/shm_test_client.hpp"
#include "io/shm_lowlevel/shm_test_names.hpp"

namespace cerebellum {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double deg(double d) { return d * kPi / 180.0; }

// the client's stand-up, written here independently: current -> lying (1 s) -> stand (1.5 s)
JointArray<double> stand_target(double t_s, const JointArray<double>& start) {
  const double lying[3] = {0.0, deg(80.0), deg(-135.0)};
  const double stand[3] = {0.0, deg(45.0), deg(-70.0)};
  JointArray<double> q{};
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    if (t_s < 1.0) {
      q[i] = start[i] + (lying[i % 3] - start[i]) * t_s;
    } else {
      const double s = std::min((t_s - 1.0) / 1.5, 1.0);
      q[i] = lying[i % 3] + (stand[i % 3] - lying[i % 3]) * s;
    }
  }
  return q;
}

// takes the robot whenever the MC lets it, commands the motors passive with light damping
class GreedySource final : public LowLevelSource {
 public:
  const char* name() const override { return "the greedy test source"; }
  bool wants_control() const override { return true; }
  void on_latched(const RobotState&) override { latched = true; }
  void on_refused(const char*) override {}
  void compute(const RobotState&, JointCommand& command) override {
    command = JointCommand{};
    command.kd.fill(0.5);
  }
  bool latched = false;
};

class ShmLockstep : public ::testing::Test {
 protected:
  void build(Startup startup, LowLevelSource* first_source = nullptr) {
    config_ = default_config();
    config_.loop_period_s = 0.001;  // one tick per 1 ms cycle: the client acts every cycle
    config_.startup = startup;
    config_.shm.enabled = true;
    config_.shm.name_prefix = unique_shm_prefix();
    mc_ = std::make_unique<Mc>(config_, make_simulated_robot(config_.robot));
    log_ = std::tmpfile();
    ASSERT_NE(log_, nullptr);
    port_ = std::make_unique<ShmLowLevelPort>(config_.shm, config_.safety, log_);
    if (first_source != nullptr) mc_->arbiter().add_low_level_source(*first_source);
    mc_->arbiter().add_low_level_source(port_->source());
    mc_->loop().add_substep_participant(*port_);
    client_ = std::make_unique<ShmTestClient>(port_->spline_object_name(), port_->imu_object_name());
  }

  void TearDown() override {
    client_.reset();
    port_.reset();
    if (log_ != nullptr) std::fclose(log_);
  }

  void tick() { mc_->loop().tick(); }
  const ShmLowLevelSource& source() const { return port_->source(); }
  double height_m() const { return mc_->simulation().ground_truth().position[2]; }
  double robot_time_s() const { return mc_->backend().time_s(); }

  // one tick without a command, then the stand-up for duration_s, one frame per cycle
  void stand_up(double duration_s) {
    tick();
    JointArray<double> start{};
    ASSERT_TRUE(client_->read_state(start));
    const int cycles = static_cast<int>(std::lround(duration_s / 0.001));
    for (int k = 0; k < cycles; ++k) {
      ASSERT_TRUE(client_->send(stand_target(0.001 * k, start), 60.0f, 2.0f)) << "cycle " << k;
      tick();
    }
  }

  std::string log_text() {
    port_->flush_log();
    std::fflush(log_);
    std::rewind(log_);
    std::string text;
    char buffer[512];
    while (std::fgets(buffer, sizeof(buffer), log_) != nullptr) text += buffer;
    return text;
  }

  static int count(const std::string& text, const std::string& fragment) {
    int n = 0;
    for (std::size_t at = text.find(fragment); at != std::string::npos; at = text.find(fragment, at + 1)) ++n;
    return n;
  }

  McConfig config_;
  std::unique_ptr<Mc> mc_;
  std::FILE* log_ = nullptr;
  std::unique_ptr<ShmLowLevelPort> port_;
  std::unique_ptr<ShmTestClient> client_;
};

TEST_F(ShmLockstep, ClientStandsTheRobot) {
  build(Startup::Damper);
  stand_up(3.5);
  EXPECT_TRUE(source().latched());
  EXPECT_EQ(mc_->arbiter().latched(), &port_->source());
  EXPECT_GE(height_m(), 0.2);
  const ShmLowLevelCounters c = source().counters();
  EXPECT_EQ(c.frames_taken, 3500u);
  EXPECT_EQ(c.frames_rejected, 0u);
  EXPECT_EQ(c.missed_cycles, 0u);
  EXPECT_EQ(c.command_timeouts, 0u);
  // the legs reached the stand pose (SDK convention, no sign flip on the way)
  JointArray<double> q{};
  ASSERT_TRUE(client_->read_state(q));
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    const double target = i % 3 == 0 ? 0.0 : i % 3 == 1 ? deg(45.0) : deg(-70.0);
    EXPECT_NEAR(q[i], target, 0.08) << "joint " << i;
  }
  EXPECT_EQ(count(log_text(), "low-level client took control"), 1);
}

TEST_F(ShmLockstep, SilenceClearsTheCommandAfterTenCycles) {
  build(Startup::Damper);
  stand_up(3.0);
  const double last_frame_s = robot_time_s() - 0.001;  // the frame was taken at the start of the last cycle
  const double standing_m = height_m();
  ASSERT_GE(standing_m, 0.2);
  // nine missed cycles: the last frame repeats
  for (int missed = 1; missed <= 9; ++missed) {
    tick();
    ASSERT_TRUE(source().command_active()) << missed;
    EXPECT_EQ(source().active_command().kp[4], 60.0) << missed;
  }
  // the tenth: damping, 10 ms of robot time after the last frame
  tick();
  EXPECT_FALSE(source().command_active());
  EXPECT_NEAR(robot_time_s() - 0.001 - last_frame_s, 0.010, 1e-9);
  const JointCommand& damped = source().active_command();
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    EXPECT_EQ(damped.kp[i], 0.0);
    EXPECT_EQ(damped.kd[i], config_.safety.damping_kd);
    EXPECT_EQ(damped.tau_ff[i], 0.0);
    EXPECT_EQ(damped.qd_des[i], 0.0);
  }
  EXPECT_EQ(source().counters().command_timeouts, 1u);
  EXPECT_EQ(source().counters().missed_cycles, 10u);
  EXPECT_EQ(count(log_text(), "no command frame for 10 cycles: command cleared, motors damped (kp 0, kd 4.00, tau 0)"),
            1);
  // the damped robot sinks
  for (int k = 0; k < 2000; ++k) tick();
  EXPECT_LT(height_m(), standing_m - 0.05);
  // a new frame takes over again
  JointArray<double> q{};
  ASSERT_TRUE(client_->read_state(q));
  ASSERT_TRUE(client_->send(q, 60.0f, 2.0f));
  tick();
  EXPECT_TRUE(source().command_active());
  EXPECT_EQ(source().active_command().kp[0], 60.0);
  EXPECT_EQ(count(log_text(), "command frames resumed"), 1);
}

TEST_F(ShmLockstep, StateFlagsAndContentFollowTheHandshake) {
  build(Startup::Damper);
  // nothing published before the first cycle
  EXPECT_EQ(client_->state_flag(CONSUMER_CONTROL), 0u);
  EXPECT_EQ(client_->state_flag(CONSUMER_OTHER), 0u);
  const SensorFrame before = mc_->backend().read();
  tick();
  EXPECT_EQ(client_->state_flag(CONSUMER_CONTROL), 1u);
  EXPECT_EQ(client_->state_flag(CONSUMER_OTHER), 1u);
  // the frame of the cycle's start, as the client sees it through the vendor structs
  const spline_state_data_t& state = client_->shm()->state;
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    const joint_state_t joints[3] = {state.legs[leg].abad, state.legs[leg].hip, state.legs[leg].knee};
    for (std::size_t j = 0; j < 3; ++j) {
      const std::size_t i = 3 * leg + j;
      EXPECT_EQ(joints[j].p, static_cast<float>(before.q[i])) << i;
      EXPECT_EQ(joints[j].v, static_cast<float>(before.qd[i])) << i;
      EXPECT_EQ(joints[j].t, static_cast<float>(before.tau[i])) << i;
      const int temperature_byte = static_cast<int>(std::lround(before.temperature_c[i])) + 40;
      // bus voltage: the simulated battery's, in whole volts
      const int volts = static_cast<int>(std::lround(before.battery.voltage_v));
      EXPECT_EQ(joints[j].flags, 1 + 256 * temperature_byte + 65536 * volts) << i;
    }
    EXPECT_EQ(state.legs[leg].foot.flags, 0);
    EXPECT_EQ(state.legs[leg].foot.p, 0.0f);
  }
  const nav_imu_t& imu = *client_->imu();
  const std::size_t first_stamp_ns = imu.timestamp;  // the memory is live: keep the value
  EXPECT_EQ(first_stamp_ns, static_cast<std::size_t>(std::llround(before.time_s * 1e9)));
  for (int k = 0; k < 4; ++k) EXPECT_EQ(imu.q[k], static_cast<float>(before.imu_quat[k]));
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(imu.acc[k], static_cast<float>(before.imu_accel[k]));
    EXPECT_EQ(imu.gyro[k], static_cast<float>(before.imu_gyro[k]));
  }

  // the controller clears its flag by reading; the other consumer's stays
  JointArray<double> q{};
  nav_imu_t read_imu{};
  ASSERT_TRUE(client_->read_state(q, &read_imu));
  EXPECT_EQ(read_imu.timestamp, first_stamp_ns);
  EXPECT_EQ(client_->state_flag(CONSUMER_CONTROL), 0u);
  EXPECT_EQ(client_->state_flag(CONSUMER_OTHER), 1u);
  EXPECT_FALSE(client_->read_state(q)) << "no new frame yet";
  tick();
  EXPECT_EQ(client_->state_flag(CONSUMER_CONTROL), 1u);
  ASSERT_TRUE(client_->read_state(q, &read_imu));
  EXPECT_EQ(read_imu.timestamp, first_stamp_ns + 1000000u) << "one frame per 1 ms of robot time";

  // command: the MC takes a flagged frame and clears the flag
  JointArray<double> hold{};
  ASSERT_TRUE(client_->send(q, 60.0f, 2.0f));
  EXPECT_EQ(client_->command_flag(), 1u);
  EXPECT_FALSE(client_->send(hold, 1.0f, 0.0f)) << "the previous frame is not taken yet: nothing written";
  EXPECT_EQ(client_->shm()->cmd.legs[0].abad.kp, 60.0f);
  tick();
  EXPECT_EQ(client_->command_flag(), 0u);
  EXPECT_EQ(source().counters().frames_taken, 1u);
  // without a new flag nothing is taken: the frame repeats
  tick();
  EXPECT_EQ(source().counters().frames_taken, 1u);
  EXPECT_EQ(source().counters().missed_cycles, 1u);
  EXPECT_TRUE(source().latched());
  EXPECT_EQ(source().active_command().kp[0], 60.0);
}

TEST_F(ShmLockstep, NonFiniteOrAbsurdFramesAreRejectedAndLogged) {
  build(Startup::Damper);
  stand_up(1.0);
  const JointCommand good = source().active_command();
  const auto expect_unchanged = [&] {
    const JointCommand& now = source().active_command();
    for (std::size_t i = 0; i < kNumJoints; ++i) {
      EXPECT_EQ(now.q_des[i], good.q_des[i]) << i;
      EXPECT_EQ(now.kp[i], good.kp[i]) << i;
      EXPECT_EQ(now.kd[i], good.kd[i]) << i;
    }
  };
  JointArray<double> q{};
  ASSERT_TRUE(client_->read_state(q));
  leg_control_t frame[4];

  ShmTestClient::position_frame(q, 60.0f, 2.0f, frame);
  frame[FRONT_LEFT].hip.p_des = std::numeric_limits<float>::quiet_NaN();
  ASSERT_TRUE(client_->send_raw(frame));
  tick();
  EXPECT_EQ(source().counters().frames_rejected, 1u);
  EXPECT_EQ(client_->command_flag(), 0u) << "a rejected frame is still taken off the flag";
  expect_unchanged();

  ShmTestClient::position_frame(q, 60.0f, 2.0f, frame);
  frame[BACK_RIGHT].knee.t_ff = std::numeric_limits<float>::infinity();
  ASSERT_TRUE(client_->send_raw(frame));
  tick();
  ShmTestClient::position_frame(q, 1e6f, 2.0f, frame);
  ASSERT_TRUE(client_->send_raw(frame));
  tick();
  ShmTestClient::position_frame(q, 60.0f, -2.0f, frame);
  ASSERT_TRUE(client_->send_raw(frame));
  tick();
  EXPECT_EQ(source().counters().frames_rejected, 4u);
  expect_unchanged();
  EXPECT_TRUE(source().command_active());

  const std::string log = log_text();
  EXPECT_EQ(count(log, "FL hip p_des = nan (not finite)"), 1) << log;
  EXPECT_EQ(count(log, "RR knee t_ff = inf (not finite)"), 1) << log;
  EXPECT_EQ(count(log, "FR abad kp = 1e+06 (gain out of range)"), 1) << log;
  EXPECT_EQ(count(log, "FR abad kd = -2 (gain out of range)"), 1) << log;

  // garbage in the unused foot entries is not read
  ShmTestClient::position_frame(q, 60.0f, 2.0f, frame);
  frame[FRONT_RIGHT].foot.kp = std::numeric_limits<float>::quiet_NaN();
  ASSERT_TRUE(client_->send_raw(frame));
  tick();
  EXPECT_EQ(source().counters().frames_rejected, 4u);

  // rejected frames count as missing ones: only bad frames for 10 cycles drop the command
  frame[FRONT_RIGHT].abad.kd = std::numeric_limits<float>::quiet_NaN();
  for (int k = 0; k < 10; ++k) {
    ASSERT_TRUE(client_->send_raw(frame));
    tick();
  }
  EXPECT_FALSE(source().command_active());
  EXPECT_EQ(source().active_command().kp[0], 0.0);
}

TEST_F(ShmLockstep, RefusedWhileAnotherSourceHoldsTheRobot) {
  GreedySource greedy;
  build(Startup::Damper, &greedy);
  tick();
  tick();
  ASSERT_TRUE(greedy.latched);
  stand_up(1.5);
  EXPECT_FALSE(source().latched());
  EXPECT_EQ(mc_->arbiter().latched(), &greedy);
  // one refusal per tick while the client keeps sending, one log line for the whole stretch
  EXPECT_GE(source().counters().refusals, 1499u);
  EXPECT_EQ(count(log_text(), "command frames ignored: the greedy test source has the robot"), 1);
  EXPECT_LT(height_m(), 0.15) << "the frames must not have moved the robot";
  // the state is still published for the client to read
  JointArray<double> q{};
  EXPECT_TRUE(client_->read_state(q));
}

TEST_F(ShmLockstep, RefusedWhileTheMcStandsByItself) {
  build(Startup::Stand);
  // limp frames: if they reached the motors the robot could not stand
  tick();
  const JointArray<double> zero{};
  for (int k = 0; k < 3000; ++k) {
    ASSERT_TRUE(client_->send(zero, 0.0f, 0.0f));
    tick();
  }
  EXPECT_FALSE(source().latched());
  EXPECT_EQ(mc_->arbiter().latched(), nullptr);
  EXPECT_GE(height_m(), 0.2);
  EXPECT_EQ(count(log_text(), "command frames ignored: the MC (not in Off or PureDamper) has the robot"), 1);
}

TEST_F(ShmLockstep, ObjectsAreRemovedWithThePort) {
  build(Startup::Damper);
  const std::string spline = port_->spline_object_name();
  const std::string imu = port_->imu_object_name();
  EXPECT_TRUE(shm_object_exists(spline));
  EXPECT_TRUE(shm_object_exists(imu));
  client_.reset();
  port_.reset();
  EXPECT_FALSE(shm_object_exists(spline));
  EXPECT_FALSE(shm_object_exists(imu));
}

}  // namespace
}  // namespace cerebellum
