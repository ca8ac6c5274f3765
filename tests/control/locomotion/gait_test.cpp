// Gait schedules against the firmware's table.
#include "control/locomotion/gait.hpp"

#include <gtest/gtest.h>

namespace cerebellum {
namespace {

TEST(Gait, TableFactsForEachGait) {
  struct Row {
    int id, period, stance;
    std::array<int, 4> offsets;
  };
  for (const Row& r : {Row{27, 20, 12, {0, 10, 10, 0}}, Row{3, 12, 6, {0, 6, 6, 0}}, Row{10, 10, 4, {0, 5, 5, 0}},
                       Row{4, 12, 6, {0, 6, 6, 0}}, Row{2, 10, 4, {0, 0, 0, 0}}, Row{7, 12, 8, {6, 6, 0, 0}},
                       Row{1, 10, 10, {0, 0, 0, 0}}, Row{31, 10, 10, {0, 0, 0, 0}}}) {
    const auto p = gait_pattern(r.id);
    ASSERT_TRUE(p.has_value()) << r.id;
    EXPECT_EQ(p->period_segments, r.period) << r.id;
    EXPECT_EQ(p->stance[0], r.stance) << r.id;
    EXPECT_EQ(p->offsets, r.offsets) << r.id;
  }
  EXPECT_FALSE(gait_pattern(5).has_value());
  EXPECT_FALSE(gait_pattern(110).has_value());
}

TEST(Gait, VelocityLimitsOfTheReference) {
  const auto flying = gait_pattern(10);
  EXPECT_EQ(flying->velocity_max[0], 1.6);
  EXPECT_EQ(flying->velocity_min[0], -1.2);
  EXPECT_EQ(flying->velocity_max[2], 2.5);
  EXPECT_EQ(gait_pattern(27)->velocity_max[1], 0.2);
}

TEST(Gait, VariableTrotShortensItsCycleAsSpeedGrows) {
  EXPECT_EQ(variable_trot_pattern(0.0).period_segments, 24);
  EXPECT_EQ(variable_trot_pattern(0.0).stance[0], 16);
  EXPECT_EQ(variable_trot_pattern(0.45).period_segments, 20);
  EXPECT_EQ(variable_trot_pattern(1.6).period_segments, 10);
  EXPECT_EQ(variable_trot_pattern(1.6).stance[0], 5);
  EXPECT_EQ(variable_trot_pattern(-1.0).period_segments, 14);
}

TEST(Gait, TrotSchedulePairsDiagonalLegs) {
  GaitScheduler scheduler(0.03);
  scheduler.set_pattern(*gait_pattern(3));
  const auto table = scheduler.horizon_contacts<12>();
  for (int k = 0; k < 12; ++k) {
    EXPECT_EQ(table[k][0], table[k][3]) << k;  // FR with RL
    EXPECT_EQ(table[k][1], table[k][2]) << k;  // FL with RR
    EXPECT_NE(table[k][0], table[k][1]) << k;
    EXPECT_EQ(table[k][0], k < 6) << k;
  }
}

TEST(Gait, PhasesAdvanceThroughStanceAndSwing) {
  GaitScheduler scheduler(0.03);
  scheduler.set_pattern(*gait_pattern(3));  // 6 segments stance, 6 swing
  scheduler.advance(0.09);                  // 3 segments
  LegPhase fr = scheduler.leg_phase(0);
  EXPECT_TRUE(fr.stance);
  EXPECT_NEAR(fr.stance_phase, 0.5, 1e-9);
  EXPECT_NEAR(fr.stance_duration_s, 0.18, 1e-12);
  const LegPhase fl = scheduler.leg_phase(1);
  EXPECT_FALSE(fl.stance);
  EXPECT_NEAR(fl.swing_phase, 0.5, 1e-9);
  scheduler.advance(0.36);  // a whole cycle later: the same
  fr = scheduler.leg_phase(0);
  EXPECT_NEAR(fr.stance_phase, 0.5, 1e-9);
}

TEST(Gait, StandsDoNotStepAndTheBridgeKeepsEveryFootDown) {
  for (const GaitSpec& gait : kGaitTable)
    EXPECT_EQ(steps(*gait_pattern(gait.id)), gait.kind != GaitKind::Stand) << gait.id;
  const GaitPattern bridge = stand_bridge_pattern(2);
  EXPECT_FALSE(steps(bridge));
  GaitScheduler scheduler(0.03);
  scheduler.set_pattern(bridge);
  for (int tick = 0; tick < 60; ++tick) {
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) EXPECT_TRUE(scheduler.leg_phase(leg).stance);
    scheduler.advance(0.002);
  }
  EXPECT_EQ(stand_bridge_pattern(0).period_segments, 1);  // never an empty cycle
}

TEST(Gait, SwitchingPatternKeepsTheCyclePhase) {
  GaitScheduler scheduler(0.03);
  scheduler.set_pattern(*gait_pattern(27));
  scheduler.advance(0.15);  // 5 of 20 segments
  EXPECT_NEAR(scheduler.cycle_phase(), 0.25, 1e-9);
  scheduler.set_pattern(*gait_pattern(3));
  EXPECT_NEAR(scheduler.cycle_phase(), 0.25, 1e-9);
}

TEST(Gait, RestartingFromAStandBeginsTheNewGaitAtItsCycleStartWhereverTheStandWas) {
  GaitScheduler scheduler(0.03);
  scheduler.set_pattern(*gait_pattern(kStandGaitId));
  scheduler.advance(0.21);  // 7 of the stand's 10 segments
  scheduler.restart(*gait_pattern(3));
  EXPECT_NEAR(scheduler.cycle_phase(), 0.0, 1e-12);
  // the trot's first swing pair (FL, RR) lifts now, for its whole swing
  const LegPhase fl = scheduler.leg_phase(1);
  EXPECT_FALSE(fl.stance);
  EXPECT_NEAR(fl.swing_phase, 0.0, 1e-12);
  EXPECT_TRUE(scheduler.leg_phase(0).stance);
}

// the feet that stand alone first after a cycle begins at `segment`, read off the scheduler's
// horizon (independent of entry_segment's own walk through the pattern)
std::array<bool, kNumLegs> first_lone_stance(const GaitPattern& pattern, int segment) {
  GaitScheduler scheduler(0.03);
  scheduler.restart(pattern, segment);
  for (const auto& contact : scheduler.horizon_contacts<12>()) {
    if (!(contact[0] && contact[1] && contact[2] && contact[3])) return contact;
  }
  return {true, true, true, true};
}

TEST(Gait, ABoundBeginsWithTheRearPairAloneWhenTheFeetStandUnderTheHips) {
  const GaitPattern bound = *gait_pattern(7);
  const int segment = entry_segment(bound, {-0.11, 0.11, -0.11, 0.11});
  EXPECT_EQ(segment, 0);
  const std::array<bool, kNumLegs> rear_alone{false, false, true, true};
  EXPECT_EQ(first_lone_stance(bound, segment), rear_alone);
}

TEST(Gait, ABoundBeginsWithTheFrontPairAloneWhenARearFootStandsUnderTheBody) {
  // a sideways trot left the rear right foot 1 cm from the centre line
  const GaitPattern bound = *gait_pattern(7);
  const int segment = entry_segment(bound, {-0.11, 0.13, -0.01, 0.12});
  const std::array<bool, kNumLegs> front_alone{true, true, false, false};
  EXPECT_EQ(first_lone_stance(bound, segment), front_alone);
  // it begins where every foot stands, not in the middle of a swing
  GaitScheduler scheduler(0.03);
  scheduler.restart(bound, segment);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) EXPECT_TRUE(scheduler.leg_phase(leg).stance) << leg;
  // and a front foot under the body keeps the rear pair first
  EXPECT_EQ(first_lone_stance(bound, entry_segment(bound, {-0.02, 0.12, -0.11, 0.11})),
            (std::array<bool, kNumLegs>{false, false, true, true}));
}

TEST(Gait, GaitsWithoutALonePairBeginAtTheirCycleStartWhereverTheFeetAre) {
  for (int id : {27, 3, 10, 4, 2}) {
    EXPECT_EQ(entry_segment(*gait_pattern(id), {-0.01, 0.12, -0.11, 0.01}), 0) << id;
  }
  EXPECT_EQ(entry_segment(variable_trot_pattern(1.0), {0.0, 0.0, 0.0, 0.0}), 0);
}

TEST(Gait, OnlyAGaitInWhichAFrontOrRearPairStandsAloneStandsOnLonePairs) {
  EXPECT_TRUE(stands_on_lone_pairs(*gait_pattern(7)));  // the bound
  for (int id : {27, 3, 10, 4, 2, 1, 31}) EXPECT_FALSE(stands_on_lone_pairs(*gait_pattern(id))) << id;
  EXPECT_FALSE(stands_on_lone_pairs(variable_trot_pattern(1.0)));
  EXPECT_FALSE(stands_on_lone_pairs(stand_bridge_pattern(3)));
  // hand-made cycles of 8 segments (FR, FL, RR, RL): a trot whose diagonals meet in segment 3,
  // where only the front pair stands; a walk, one foot up at a time, never; each pair alone in
  // turn, with a flight
  GaitPattern pattern = *gait_pattern(7);
  pattern.period_segments = 8;
  pattern.offsets = {0, 3, 4, 0};
  pattern.stance = {4, 5, 4, 3};
  EXPECT_TRUE(stands_on_lone_pairs(pattern));
  pattern.stance = {4, 5, 4, 4};  // the rear left foot stays into segment 3: three feet down there
  EXPECT_FALSE(stands_on_lone_pairs(pattern));
  pattern.offsets = {0, 2, 4, 6};
  pattern.stance = {6, 6, 6, 6};
  EXPECT_FALSE(stands_on_lone_pairs(pattern));
  pattern.offsets = {4, 4, 0, 0};
  pattern.stance = {2, 2, 4, 4};
  EXPECT_TRUE(stands_on_lone_pairs(pattern));
}

TEST(Gait, ATrotLeavingAStandSidewaysBeginsWithTheDiagonalWhoseRearFootIsOnTheSideTheBodyMovesToward) {
  const std::array<bool, kNumLegs> rear_left_diagonal{true, false, false, true};   // FR, RL stand
  const std::array<bool, kNumLegs> rear_right_diagonal{false, true, true, false};  // FL, RR stand
  for (int id : {27, 3, 10}) {
    const GaitPattern trot = *gait_pattern(id);
    EXPECT_EQ(first_lone_stance(trot, sideways_entry_segment(trot, 0.5, 0.1)), rear_left_diagonal) << id;
    EXPECT_EQ(first_lone_stance(trot, sideways_entry_segment(trot, -0.5, 0.1)), rear_right_diagonal) << id;
    // moving right, the first swing is whole: the swinging diagonal lifts at the start of its swing
    GaitScheduler scheduler(0.03);
    scheduler.restart(trot, sideways_entry_segment(trot, -0.5, 0.1));
    EXPECT_TRUE(scheduler.leg_phase(static_cast<std::size_t>(Leg::RR)).stance) << id;
    EXPECT_NEAR(scheduler.leg_phase(static_cast<std::size_t>(Leg::RR)).stance_phase, 0.0, 1e-12) << id;
  }
  const GaitPattern variable = variable_trot_pattern(1.0);
  EXPECT_EQ(first_lone_stance(variable, sideways_entry_segment(variable, -0.5, 0.1)), rear_right_diagonal);
}

TEST(Gait, ATrotAfterABoundBeginsWithTheDiagonalWhoseLinePassesNearerTheCentre) {
  const std::array<bool, kNumLegs> rear_left_diagonal{true, false, false, true};   // FR, RL stand
  const std::array<bool, kNumLegs> rear_right_diagonal{false, true, true, false};  // FL, RR stand
  // feet (x, y from the centre; FR, FL, RR, RL) at the corners of a 0.4 x 0.2 m rectangle: both
  // diagonals pass through the centre
  std::array<Eigen::Vector2d, kNumLegs> feet{{{0.2, -0.1}, {0.2, 0.1}, {-0.2, -0.1}, {-0.2, 0.1}}};
  // the rear right foot 6 cm outward: the FL-RR line passes 0.2 * 0.06 / |(-0.4, -0.26)| = 2.5 cm
  // from the centre, the FR-RL line still through it
  feet[2] = {-0.2, -0.16};
  for (int id : {27, 3, 10, 26}) {
    const GaitPattern trot = id == 26 ? variable_trot_pattern(0.5) : *gait_pattern(id);
    EXPECT_EQ(first_lone_stance(trot, diagonal_entry_segment(trot, feet)), rear_left_diagonal) << id;
  }
  // the rear left foot 6 cm outward instead: the mirror image
  feet[2] = {-0.2, -0.1};
  feet[3] = {-0.2, 0.16};
  for (int id : {27, 3, 10}) {
    const GaitPattern trot = *gait_pattern(id);
    EXPECT_EQ(first_lone_stance(trot, diagonal_entry_segment(trot, feet)), rear_right_diagonal) << id;
  }
  // 4 cm outward: the line passes 0.2 * 0.04 / |(-0.4, 0.24)| = 1.7 cm away; 2 cm: 0.9 cm, within
  // the 1 cm preference, so the cycle begins at its start
  feet[3] = {-0.2, 0.14};
  EXPECT_EQ(first_lone_stance(*gait_pattern(27), diagonal_entry_segment(*gait_pattern(27), feet)), rear_right_diagonal);
  feet[3] = {-0.2, 0.12};
  EXPECT_EQ(diagonal_entry_segment(*gait_pattern(27), feet), 0);
  // a gait that is no trot begins at its cycle start
  feet[3] = {-0.2, 0.16};
  for (int id : {7, 2, kStandGaitId}) EXPECT_EQ(diagonal_entry_segment(*gait_pattern(id), feet), 0) << id;
}

TEST(Gait, ASlowBodyOrAGaitThatIsNoTrotBeginsAtItsCycleStart) {
  EXPECT_EQ(sideways_entry_segment(*gait_pattern(10), -0.05, 0.1), 0);
  for (int id : {7, 2, kStandGaitId}) EXPECT_EQ(sideways_entry_segment(*gait_pattern(id), -0.5, 0.1), 0) << id;
}

}  // namespace
}  // namespace cerebellum
