// The IMU fields of every interface read what an IMU reads: the specific force, the acceleration
// minus gravity's (+9.81 m/s^2 up at rest, zero in free fall), in the frame each field names.
// The whole MC runs in lockstep on the simulated robot; each tick's fields go through the wires'
// own encoders (state_estimator_lcmt: aBody, and aWorld, which the motor SDK copies into
// RobotData.acc; the shared memory's nav_imu_t.acc; the AlienGo HighState bytes read through the
// vendor's struct) and are judged on the simulation's truth: standing at rest, falling freely (a
// drop, and a jump's flight) and lying at rest on a 10-degree ramp.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

#include "backend/sim_fixture.hpp"
#include "core/robot_model.hpp"
#include "core/specific_force.hpp"
#include "cycle/substep_participant.hpp"
#include "io/lcm_motor_sdk/robot_state_messages.hpp"
#include "io/shm_lowlevel/shm_codec.hpp"
#include "io/udp_aliengo/aliengo_wire.hpp"
#include "loop/lockstep_client.hpp"
#include "loop/simulated_robot.hpp"
#include "unitree_legged_sdk/comm.h"

namespace cerebellum {
namespace {

constexpr double kTickS = 0.002;

// at each tick's first substep: the sensor frame the shared-memory port publishes (read at the
// robot time of the tick's own frame) and the truth then and one physics step before; it never
// replaces the command
class FrameTap final : public SubstepParticipant {
 public:
  explicit FrameTap(const Simulation& simulation) : simulation_(simulation) {}
  void arm() { armed_ = true; }
  const SensorFrame& frame() const { return frame_; }
  const GroundTruth& truth() const { return truth_; }
  const GroundTruth& truth_step_before() const { return truth_step_before_; }
  double step_s() const { return step_s_; }
  bool on_substep(const SensorFrame& frame, JointCommand&) override {
    const GroundTruth now = simulation_.ground_truth();
    if (armed_) {
      frame_ = frame;
      truth_ = now;
      truth_step_before_ = last_;
      step_s_ = simulation_.time_s() - last_time_s_;
    }
    last_ = now;
    last_time_s_ = simulation_.time_s();
    armed_ = false;
    return false;
  }

 private:
  const Simulation& simulation_;
  bool armed_ = false;
  SensorFrame frame_;
  GroundTruth truth_, truth_step_before_, last_;
  double step_s_ = 0.0, last_time_s_ = 0.0;
};

Eigen::Vector3d vec(const float (&v)[3]) { return {v[0], v[1], v[2]}; }

// one tick's IMU fields as each interface publishes them, m/s^2
struct WireImu {
  Eigen::Vector3d estimator_body;   // state_estimator.aBody
  Eigen::Vector3d estimator_world;  // state_estimator.aWorld (the motor SDK's RobotData.acc)
  Eigen::Vector3d shm_body;         // nav_imu_t.acc
  Eigen::Vector3d aliengo_body;     // HighState.imu.accelerometer
};

WireImu encode_all(const CycleRecord& record, const SensorFrame& frame) {
  WireImu wire;
  const state_estimator_lcmt estimator = make_state_estimator(record.state);
  wire.estimator_body = vec(estimator.aBody);
  wire.estimator_world = vec(estimator.aWorld);
  nav_imu_t imu{};
  encode_shm_imu(frame, imu);
  wire.shm_body = vec(imu.acc);
  std::uint8_t bytes[kHighStateBytes];
  encode_high_state(make_feedback(record.state, 1), bytes);
  // the vendor's HighState is packed: its floats are not aligned, so they are copied out of the
  // bytes at the struct's own offsets rather than read through a reference
  float accelerometer[3];
  std::memcpy(accelerometer,
              bytes + offsetof(UNITREE_LEGGED_SDK::HighState, imu) + offsetof(UNITREE_LEGGED_SDK::IMU, accelerometer),
              sizeof accelerometer);
  wire.aliengo_body = vec(accelerometer);
  return wire;
}

// one tick: the truth when its sensors were read, and what the interfaces published
struct Sample {
  GroundTruth truth;
  GroundTruth truth_step_before;  // one physics step before
  double step_s = 0.0;
  WireImu wire;
};

Eigen::Matrix3d body_to_world(const GroundTruth& truth) {
  return Eigen::Quaterniond(truth.quat[0], truth.quat[1], truth.quat[2], truth.quat[3]).toRotationMatrix();
}

double speed_m_s(const GroundTruth& truth) { return Eigen::Vector3d(truth.velocity_world.data()).norm(); }

bool in_the_air(const GroundTruth& truth) {
  return std::none_of(truth.foot_contact.begin(), truth.foot_contact.end(), [](bool c) { return c; });
}

// the velocity (world) of the IMU's point, from the truth of the trunk
Eigen::Vector3d imu_velocity_world(const GroundTruth& truth) {
  const Eigen::Vector3d imu(robot::kImuPositionBody[0], robot::kImuPositionBody[1], robot::kImuPositionBody[2]);
  const Eigen::Vector3d omega_body(truth.angular_velocity_body.data());
  return Eigen::Vector3d(truth.velocity_world.data()) + body_to_world(truth) * omega_body.cross(imu);
}

// what the IMU should read, world frame, from the truth: its point's change of velocity over the
// physics step before the sample, plus gravity's reaction
Eigen::Vector3d truth_specific_force_world(const Sample& s) {
  return (imu_velocity_world(s.truth) - imu_velocity_world(s.truth_step_before)) / s.step_s +
         specific_force_at_rest_world();
}

McConfig start_config(Startup startup, const std::string& model = "") {
  McConfig config = default_config();
  config.startup = startup;
  if (!model.empty()) config.robot.model_path = std::string(CEREBELLUM_MODEL_DIR) + "/" + model;
  return config;
}

// the MC on the simulated robot, a client in lockstep, and the tap
struct ImuRun {
  explicit ImuRun(const McConfig& config) : mc(make_simulated_mc(config)), client(mc), tap(mc.simulation()) {
    mc.loop().add_substep_participant(tap);
  }

  GroundTruth truth() { return mc.simulation().ground_truth(); }

  // runs the command for seconds; each(sample) sees every tick
  template <typename Each>
  void run(const HighLevelCommand& command, double seconds, Each&& each) {
    tap.arm();
    client.run(command, seconds, [&](const CycleRecord& record) {
      each(Sample{tap.truth(), tap.truth_step_before(), tap.step_s(), encode_all(record, tap.frame())});
      tap.arm();
    });
  }
  void run(const HighLevelCommand& command, double seconds) {
    run(command, seconds, [](const Sample&) {});
  }
  std::vector<Sample> record(const HighLevelCommand& command, double seconds) {
    std::vector<Sample> samples;
    run(command, seconds, [&](const Sample& s) { samples.push_back(s); });
    return samples;
  }

  Mc mc;
  LockstepClient client;
  FrameTap tap;
};

// each field's distance from what it should read: the largest over the samples, and that of the
// mean (body-frame fields compared in the body frame of each sample)
class FieldErrors {
 public:
  void add(const WireImu& wire, const Eigen::Vector3d& expected_world, const Eigen::Matrix3d& body_to_world) {
    const Eigen::Vector3d expected_body = body_to_world.transpose() * expected_world;
    const Eigen::Vector3d errors[kFields] = {wire.estimator_body - expected_body, wire.estimator_world - expected_world,
                                             wire.shm_body - expected_body, wire.aliengo_body - expected_body};
    for (int k = 0; k < kFields; ++k) {
      worst_[k] = std::max(worst_[k], errors[k].norm());
      sum_[k] += errors[k];
    }
    ++count_;
  }
  int count() const { return count_; }
  // the largest over the four fields
  double worst() const { return *std::max_element(worst_, worst_ + kFields); }
  double mean() const {
    double largest = 0.0;
    for (int k = 0; k < kFields; ++k) largest = std::max(largest, sum_[k].norm() / std::max(count_, 1));
    return largest;
  }
  // for the failure message
  std::string describe() const {
    const char* names[kFields] = {"aBody", "aWorld (RobotData.acc)", "nav_imu_t.acc", "HighState accelerometer"};
    std::string text;
    for (int k = 0; k < kFields; ++k) {
      text += std::string(names[k]) + ": worst " + std::to_string(worst_[k]) + ", mean " +
              std::to_string(sum_[k].norm() / std::max(count_, 1)) + " m/s^2 off; ";
    }
    return text;
  }

 private:
  static constexpr int kFields = 4;
  double worst_[kFields] = {};
  Eigen::Vector3d sum_[kFields] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                   Eigen::Vector3d::Zero()};
  int count_ = 0;
};

TEST(ImuSpecificForce, StandingAtRestEveryInterfaceReadsGravitysReactionUpInTheBodyAndTheWorld) {
  ImuRun run(start_config(Startup::Off));
  run.run(high_level_command(ModeId::RecoveryStand, 0), 3.0);
  FieldErrors from_truth, from_rest;
  double fastest_m_s = 0.0;
  run.run(high_level_command(ModeId::RecoveryStand, 0), 1.0, [&](const Sample& s) {
    from_truth.add(s.wire, truth_specific_force_world(s), body_to_world(s.truth));
    from_rest.add(s.wire, specific_force_at_rest_world(), body_to_world(s.truth));
    fastest_m_s = std::max(fastest_m_s, speed_m_s(s.truth));
  });
  ASSERT_LT(fastest_m_s, 0.005) << "the robot stands still";
  // what the IMU's point does, to the float rounding of the wires (measured 3e-5 m/s^2)
  EXPECT_LT(from_truth.worst(), 0.01) << from_truth.describe();
  // and that is gravity's reaction, up: the trunk's own trembling shows as about 0.002 m/s^2;
  // 0.05 (0.5 % of g) is 200 times smaller than the gravity these fields once left out
  EXPECT_LT(from_rest.worst(), 0.05) << from_rest.describe();
}

TEST(ImuSpecificForce, DroppedWithTheMotorsDampedEveryInterfaceReadsZeroInFreeFall) {
  ImuRun run(start_config(Startup::Damper));
  run.run(high_level_command(ModeId::PureDamper, 0), 1.0);
  // lying still, lifted 1 m and let go: about 0.45 s in the air
  const GroundTruth lying = run.truth();
  run.mc.simulation().set_base_pose({lying.position[0], lying.position[1], lying.position[2] + 1.0}, lying.quat);
  const std::vector<Sample> samples = run.record(high_level_command(ModeId::PureDamper, 0), 0.4);
  FieldErrors from_truth, from_zero;
  for (std::size_t n = 1; n < samples.size(); ++n) {
    ASSERT_TRUE(in_the_air(samples[n].truth)) << "tick " << n;
    from_truth.add(samples[n].wire, truth_specific_force_world(samples[n]), body_to_world(samples[n].truth));
    // the first 20 ms the legs, pressed by the trunk's weight a moment before, spring back (up to
    // 2 m/s^2 on the trunk); after that the body and its damped legs fall as one
    if (n >= static_cast<std::size_t>(0.02 / kTickS)) {
      from_zero.add(samples[n].wire, Eigen::Vector3d::Zero(), body_to_world(samples[n].truth));
    }
  }
  ASSERT_GT(from_zero.count(), 150);
  // measured 0.019 and 0.025: 0.05 is 0.5 % of g
  EXPECT_LT(from_truth.worst(), 0.05) << from_truth.describe();
  EXPECT_LT(from_zero.worst(), 0.05) << from_zero.describe();
}

TEST(ImuSpecificForce, InAJumpsFlightEveryInterfaceReadsOnlyWhatTheSwingingLegsDoToTheTrunk) {
  ImuRun run(start_config(Startup::Off));
  run.run(high_level_command(ModeId::RecoveryStand, 0), 3.0);
  run.run(high_level_command(ModeId::Locomotion, 1), 1.0);
  // the up jump (30 cm); its flight: the longest run of ticks with no foot on the ground
  const std::vector<Sample> samples = run.record(high_level_command(ModeId::Jump3d, 6), 3.0);
  std::size_t takeoff = 0, touchdown = 0;
  for (std::size_t start = 0; start < samples.size();) {
    std::size_t end = start;
    while (end < samples.size() && in_the_air(samples[end].truth)) ++end;
    if (end - start > touchdown - takeoff) takeoff = start, touchdown = end;
    start = end + 1;
  }
  ASSERT_LT(touchdown, samples.size());
  ASSERT_GT(touchdown - takeoff, static_cast<std::size_t>(0.3 / kTickS)) << "a flight of at least 0.3 s";
  // in the air only the legs push the trunk: they jerk up after take-off (-28 m/s^2 on the trunk
  // for a few ms) and then reach for the landing, so the reading swings about zero. For the first
  // 10 ms the motors' torques change from one physics step to the next, and the truth's one-step
  // difference and the reading straddle the change (up to 1.6 m/s^2 apart): left out
  FieldErrors from_truth, from_zero;
  for (std::size_t n = takeoff; n < touchdown; ++n) {
    from_zero.add(samples[n].wire, Eigen::Vector3d::Zero(), body_to_world(samples[n].truth));
    if (n >= takeoff + static_cast<std::size_t>(0.01 / kTickS)) {
      from_truth.add(samples[n].wire, truth_specific_force_world(samples[n]), body_to_world(samples[n].truth));
    }
  }
  EXPECT_LT(from_truth.worst(), 0.15) << from_truth.describe();  // measured 0.05
  // over the flight the legs' pushes and pulls average to about 0.6 m/s^2 (measured): near zero,
  // with no gravity (9.81) in it
  EXPECT_LT(from_zero.mean(), 1.0) << from_zero.describe();
}

TEST(ImuSpecificForce, LyingOnARampEveryInterfaceReadsGravitysReactionTurnedIntoTheTiltedBody) {
  ImuRun run(start_config(Startup::Damper, "terrain_slope10.xml"));
  // on the ramp (10 degrees, rising along +x from x = 1 m), turned 60 degrees from its fall line
  // so that it both rolls and pitches, let go just above the surface
  const double slope = robot::deg(10.0);
  const Eigen::Quaterniond pose = Eigen::AngleAxisd(-slope, Eigen::Vector3d::UnitY()) *
                                  Eigen::AngleAxisd(robot::deg(60.0), Eigen::Vector3d::UnitZ());
  const double x = 2.2;
  run.mc.simulation().set_base_pose({x, 0.0, (x - 1.0) * std::tan(slope) + 0.15},
                                    {pose.w(), pose.x(), pose.y(), pose.z()});
  run.run(high_level_command(ModeId::PureDamper, 0), 2.0);
  const Eigen::Vector3d rpy = testing::truth_rpy(run.truth());
  ASSERT_GT(std::abs(rpy.x()), robot::deg(4.0)) << "rolled";
  ASSERT_GT(std::abs(rpy.y()), robot::deg(4.0)) << "pitched";
  FieldErrors from_rest;
  double fastest_m_s = 0.0;
  run.run(high_level_command(ModeId::PureDamper, 0), 1.0, [&](const Sample& s) {
    from_rest.add(s.wire, specific_force_at_rest_world(), body_to_world(s.truth));
    fastest_m_s = std::max(fastest_m_s, speed_m_s(s.truth));
  });
  ASSERT_LT(fastest_m_s, 0.01) << "the robot lies still";
  // the body-frame fields read (0, 0, 9.81) turned by the truth's orientation into the body, aWorld
  // reads it upright. The robot creeps down the ramp at a few mm/s in its contacts' stick and slip,
  // whose jolts read up to 0.7 m/s^2 for a tick; over the second they average out: the mean within
  // 0.05 (0.5 % of g; measured 0.004)
  EXPECT_LT(from_rest.worst(), 1.0) << from_rest.describe();
  EXPECT_LT(from_rest.mean(), 0.05) << from_rest.describe();
}

}  // namespace
}  // namespace cerebellum
