// The viewer's keyboard driving the whole MC in lockstep robot time, judged on the simulation's
// truth: the keys go through the same KeyboardPad and PortDriver the viewer uses (the window and
// its X events are tested end to end in tests/cli/viewer_keys.*), into the machine as the
// ViewerKeyboard client. Stand, walk forward at the slow trot's top speed with W held, stop on
// its release, damp with space, stand again, jump, run a motion, lie down.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "control/locomotion/gait_table.hpp"
#include "loop/simulated_robot.hpp"
#include "teleop/keyboard_pad.hpp"
#include "teleop/port_driver.hpp"
#include "backend/sim_fixture.hpp"

namespace cerebellum {
namespace {

constexpr double kFramePeriodS = 1.0 / 60.0;  // the viewer's frames

struct KeyboardRun {
  KeyboardRun() : mc(make_simulated_mc(lying_config())), driver(mc.client_port(HighLevelSource::ViewerKeyboard)) {}

  static McConfig lying_config() {
    McConfig config = default_config();
    config.startup = Startup::Off;
    return config;
  }

  double time_s() { return mc.backend().time_s(); }
  GroundTruth truth() { return mc.simulation().ground_truth(); }

  // runs until robot time end_s, a viewer frame every kFramePeriodS; each_tick sees every cycle
  void run_until(double end_s, const std::function<void(const CycleRecord&)>& each_tick = {}) {
    while (time_s() < end_s - 1e-9) {
      if (time_s() >= next_frame_s - 1e-9) {
        const bool pressed = keys.pressed_since_sample();
        driver.drive(keys.sample(), pressed, time_s());
        next_frame_s += kFramePeriodS;
      }
      const CycleRecord& record = mc.loop().tick();
      last_mode = record.high_level.status.mode;
      if (each_tick) each_tick(record);
    }
  }
  void tap(int key_code) {
    keys.key(key_code, true);
    keys.key(key_code, false);
  }

  Mc mc;
  KeyboardPad keys;
  PortDriver driver;
  double next_frame_s = 0.0;
  int last_mode = -1;
};

double forward_speed(const GroundTruth& from, const GroundTruth& to, double seconds) {
  const double yaw = testing::truth_rpy(from).z();
  const double dx = to.position[0] - from.position[0];
  const double dy = to.position[1] - from.position[1];
  return (dx * std::cos(yaw) + dy * std::sin(yaw)) / seconds;
}

TEST(KeyboardDriveSim, APersonWithoutAGamepadStandsWalksStopsDampsJumpsRunsAMotionAndLiesDownFromTheKeys) {
  KeyboardRun run;
  run.run_until(0.5);
  run.tap('1');  // stand up
  run.run_until(3.5);
  const double standing_height_m = run.truth().position[2];
  EXPECT_GT(standing_height_m, 0.25) << "1 did not stand the robot up";

  run.tap('3');  // walk: the slow trot
  run.run_until(4.5);
  EXPECT_EQ(run.last_mode, static_cast<int>(ModeId::Locomotion));
  EXPECT_EQ(run.driver.mapping().gait_id(), kSlowTrotGaitId);
  run.keys.key('W', true);
  run.run_until(7.0);
  const GroundTruth walk_from = run.truth();
  run.run_until(11.0);
  const double speed_m_s = forward_speed(walk_from, run.truth(), 4.0);
  const double top_speed_m_s = find_gait(kSlowTrotGaitId)->velocity_max[0];
  EXPECT_NEAR(speed_m_s, top_speed_m_s, 0.1 * top_speed_m_s) << "W held walks at the gait's top speed";

  run.keys.key('W', false);
  run.run_until(13.0);
  const GroundTruth still = run.truth();
  EXPECT_LT(std::hypot(still.velocity_world[0], still.velocity_world[1]), 0.1) << "W released: the robot stops";

  run.tap(' ');  // damp, from a walk
  run.run_until(13.1);
  EXPECT_EQ(run.last_mode, static_cast<int>(ModeId::PureDamper));
  run.run_until(15.5);
  EXPECT_LT(run.truth().position[2], 0.2) << "space damped: the robot sinks down";

  run.tap('1');
  run.run_until(19.0);
  run.tap('5');  // jump: 16/6 up
  double highest_m = 0.0;
  bool jumped = false;
  run.run_until(22.0, [&](const CycleRecord& record) {
    jumped = jumped || record.high_level.status.mode == static_cast<int>(ModeId::Jump3d);
    highest_m = std::max(highest_m, run.truth().position[2]);
  });
  EXPECT_TRUE(jumped);
  EXPECT_GT(highest_m - standing_height_m, 0.15) << "5 jumps up";
  EXPECT_GT(run.truth().position[2], 0.2) << "landed standing (a jump ends in mode 11's stand, 0.235 m)";
  EXPECT_LT(testing::truth_rpy(run.truth()).head<2>().norm(), 0.2) << "landed upright";

  run.tap('1');
  run.run_until(24.0);
  run.tap('4');  // the named motion
  bool in_motion = false;
  run.run_until(25.0, [&](const CycleRecord& record) {
    in_motion = in_motion || record.high_level.status.mode == static_cast<int>(ModeId::Motion);
  });
  EXPECT_TRUE(in_motion) << "4 runs the motion";
  run.run_until(40.0);
  EXPECT_GT(run.truth().position[2], 0.2);

  run.tap('2');  // lie down
  run.run_until(43.0);
  EXPECT_LT(run.truth().position[2], 0.15) << "2 lays the robot down";
  EXPECT_EQ(run.driver.dropped(), 0u);
  EXPECT_EQ(run.mc.machine().holder(), HighLevelSource::ViewerKeyboard);
}

}  // namespace
}  // namespace cerebellum
