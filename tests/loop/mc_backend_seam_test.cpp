// The MC runs on any RobotBackend: without a simulation handle (as on hardware), and on a
// decorator wrapped around the simulated robot, with no change to Mc.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

#include "loop/simulated_robot.hpp"
#include "backend/fake_backend.hpp"

namespace cerebellum {
namespace {

// passes everything through and counts the calls: the shape of a fault-injecting decorator
class CountingBackend final : public RobotBackend {
 public:
  explicit CountingBackend(std::unique_ptr<RobotBackend> inner) : inner_(std::move(inner)) {}
  SensorFrame read() override {
    ++reads;
    return inner_->read();
  }
  void write(const JointCommand& command) override {
    ++writes;
    inner_->write(command);
  }
  void advance(double period_s) override { inner_->advance(period_s); }
  double time_s() const override { return inner_->time_s(); }

  int reads = 0;
  int writes = 0;

 private:
  std::unique_ptr<RobotBackend> inner_;
};

TEST(McBackendSeam, RunsOnARobotWithoutASimulationHandle) {
  auto fake = std::make_unique<FakeBackend>();
  const FakeBackend& robot = *fake;
  Mc mc(default_config(), McRobot{std::move(fake), nullptr});
  EXPECT_FALSE(mc.simulated());
  EXPECT_THROW(mc.simulation(), std::logic_error);
  for (int k = 0; k < 10; ++k) mc.loop().tick();
  ASSERT_EQ(robot.written().size(), 10u);
  EXPECT_EQ(robot.written().back().kd, mc.loop().last_cycle().command.kd);
  EXPECT_NEAR(mc.backend().time_s(), 10 * mc.config().loop_period_s, 1e-9);
}

TEST(McBackendSeam, ADecoratorAroundTheSimulatedRobotDrivesTheSameRobot) {
  const McConfig config = default_config();
  Mc plain = make_simulated_mc(config);
  McRobot simulated = make_simulated_robot(config.robot);
  auto counting = std::make_unique<CountingBackend>(std::move(simulated.backend));
  const CountingBackend& decorator = *counting;
  Mc decorated(config, McRobot{std::move(counting), simulated.simulation});

  const int ticks = 250;  // 0.5 s of the stand-up
  for (int k = 0; k < ticks; ++k) {
    plain.loop().tick();
    decorated.loop().tick();
  }
  EXPECT_EQ(decorator.reads, ticks);
  EXPECT_EQ(decorator.writes, ticks);
  // a pass-through decorator changes nothing: the same robot, bit for bit
  const GroundTruth a = plain.simulation().ground_truth();
  const GroundTruth b = decorated.simulation().ground_truth();
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.quat, b.quat);
  EXPECT_GT(a.position[2], 0.0);
}

}  // namespace
}  // namespace cerebellum
