// The gait table against the firmware's reference (written out here as data), and the patterns
// built from it against the table.
#include "control/locomotion/gait_table.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

#include "control/locomotion/gait.hpp"

namespace cerebellum {
namespace {

struct ReferenceGait {
  GaitKind kind;
  std::array<double, 3> velocity_min;
  std::array<double, 3> velocity_max;
};

// the reference's gaits of mode 11 with their velocity limits (vx, vy m/s; yaw rate rad/s)
const std::map<int, ReferenceGait> kReference = {
    {1, {GaitKind::Stand, {0, 0, 0}, {0, 0, 0}}},
    {2, {GaitKind::Walking, {-0.10, -0.15, -0.50}, {0.20, 0.15, 0.50}}},
    {3, {GaitKind::Walking, {-1.2, -0.4, -2.25}, {1.2, 0.4, 2.25}}},
    {4, {GaitKind::Walking, {-0.65, -0.4, -0.80}, {0.65, 0.4, 0.80}}},
    {7, {GaitKind::Walking, {-0.3, -0.3, -1.5}, {0.3, 0.3, 1.5}}},
    {10, {GaitKind::Walking, {-1.2, -0.55, -2.5}, {1.6, 0.55, 2.5}}},
    {26, {GaitKind::FrequencyAdapting, {-1.2, -0.6, -2.5}, {1.6, 0.6, 2.5}}},
    {27, {GaitKind::Walking, {-0.60, -0.2, -1.30}, {0.60, 0.2, 1.30}}},
    {31, {GaitKind::Stand, {0, 0, 0}, {0, 0, 0}}},
};

TEST(GaitTable, HoldsEachReferenceGaitOnceWithItsKindAndVelocityLimits) {
  std::set<int> listed;
  for (const GaitSpec& gait : kGaitTable) {
    EXPECT_TRUE(listed.insert(gait.id).second) << gait.id;
    ASSERT_EQ(kReference.count(gait.id), 1u) << gait.id;
    const ReferenceGait& reference = kReference.at(gait.id);
    EXPECT_EQ(gait.kind, reference.kind) << gait.id;
    EXPECT_EQ(gait.velocity_min, reference.velocity_min) << gait.id;
    EXPECT_EQ(gait.velocity_max, reference.velocity_max) << gait.id;
    EXPECT_EQ(find_gait(gait.id), &gait);
    EXPECT_GT(std::string(gait.name).size(), 0u);
  }
  EXPECT_EQ(listed.size(), kReference.size());
  EXPECT_EQ(find_gait(5), nullptr);
  EXPECT_EQ(find_gait(110), nullptr);
}

TEST(GaitTable, ContactPatternsAreSchedulableCyclesAndStandsNeverLiftAFoot) {
  for (const GaitSpec& gait : kGaitTable) {
    EXPECT_GT(gait.cycle.stance_segments, 0) << gait.id;
    EXPECT_LE(gait.cycle.stance_segments, gait.cycle.period_segments) << gait.id;
    EXPECT_EQ(gait.cycle.stance_segments == gait.cycle.period_segments, !gait_steps(gait)) << gait.id;
    for (int offset : gait.offsets) {
      EXPECT_GE(offset, 0) << gait.id;
      EXPECT_LT(offset, gait.cycle.period_segments) << gait.id;
    }
    EXPECT_GT(gait.default_step_height_m, 0.0) << gait.id;
  }
}

TEST(GaitTable, EveryPatternIsBuiltFromItsEntry) {
  for (const GaitSpec& gait : kGaitTable) {
    const auto pattern = gait_pattern(gait.id);
    ASSERT_TRUE(pattern.has_value()) << gait.id;
    EXPECT_EQ(pattern->id, gait.id);
    EXPECT_EQ(pattern->period_segments, gait.cycle.period_segments) << gait.id;
    EXPECT_EQ(pattern->offsets, gait.offsets) << gait.id;
    for (int stance : pattern->stance) EXPECT_EQ(stance, gait.cycle.stance_segments) << gait.id;
    EXPECT_EQ(pattern->velocity_min, gait.velocity_min) << gait.id;
    EXPECT_EQ(pattern->velocity_max, gait.velocity_max) << gait.id;
    EXPECT_EQ(steps(*pattern), gait_steps(gait)) << gait.id;
    EXPECT_EQ(pattern->adapts_frequency, gait.kind == GaitKind::FrequencyAdapting) << gait.id;
  }
}

TEST(GaitTable, TheVariableTrotsCyclesShortenAsSpeedGrowsAndStayTrots) {
  for (std::size_t step = 0; step < kVariableTrotCycles.size(); ++step) {
    const GaitCycle cycle = kVariableTrotCycles[step];
    if (step > 0) {
      EXPECT_LT(cycle.period_segments, kVariableTrotCycles[step - 1].period_segments);
    }
    EXPECT_LT(cycle.stance_segments, cycle.period_segments);
    // in the middle of the step's speed band
    const GaitPattern p = variable_trot_pattern((step + 0.5) * kVariableTrotSpeedPerCycleMPerS);
    EXPECT_EQ(p.id, kVariableTrotGaitId);
    EXPECT_EQ(p.period_segments, cycle.period_segments);
    EXPECT_EQ(p.offsets, (std::array<int, kNumLegs>{0, cycle.period_segments / 2, cycle.period_segments / 2, 0}));
    EXPECT_TRUE(p.adapts_frequency);
  }
}

}  // namespace
}  // namespace cerebellum
