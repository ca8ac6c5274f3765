// A contact sequence plays a user gait definition once: its runs of stance and swing per leg,
// checked against a per-segment walk of the sections, and the scheduler's phases through it.
#include "control/locomotion/contact_sequence.hpp"

#include <gtest/gtest.h>

#include <random>

#include "control/locomotion/gait.hpp"

namespace cerebellum {
namespace {

using Section = ContactSequence::Section;

// the moonwalk's shape (seed section 2.2.1) with N1..N8 = 4, 1, 5, 1, 4, 1, 5, 1
std::vector<Section> moonwalk() {
  return {{{true, true, true, true}, 4},     {{false, false, false, false}, 1}, {{false, true, true, false}, 5},
          {{false, false, false, false}, 1}, {{true, true, true, true}, 4},     {{false, false, false, false}, 1},
          {{true, false, false, true}, 5},   {{false, false, false, false}, 1}, {{true, true, true, true}, 4}};
}

TEST(ContactSequence, EverySegmentHasTheStanceOfItsSectionAndStandsOutsideTheSequence) {
  const ContactSequence sequence(moonwalk());
  ASSERT_EQ(sequence.segments(), 26);
  EXPECT_TRUE(sequence.in_stance(0, 3));
  EXPECT_FALSE(sequence.in_stance(0, 4));  // section 2: all in the air
  EXPECT_FALSE(sequence.in_stance(0, 5));  // section 3: FR swings
  EXPECT_TRUE(sequence.in_stance(1, 5));   // FL down
  EXPECT_TRUE(sequence.in_stance(2, -1));  // before: standing
  EXPECT_TRUE(sequence.in_stance(2, 26));  // after: standing
}

TEST(ContactSequence, RunsMatchAWalkOverRandomSchedules) {
  std::mt19937 random(7);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Section> sections;
    const int count = 1 + static_cast<int>(random() % 12);
    for (int i = 0; i < count; ++i) {
      Section s;
      for (bool& down : s.stance) down = random() % 2 == 0;
      s.segments = 1 + static_cast<int>(random() % 6);
      sections.push_back(s);
    }
    const ContactSequence sequence(sections);
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      for (int k = 0; k < sequence.segments(); ++k) {
        const ContactSequence::Run run = sequence.run(leg, k);
        const bool state = sequence.in_stance(leg, k);
        // the run's segments share the state, the ones just outside it do not
        int first = k;
        while (first > 0 && sequence.in_stance(leg, first - 1) == state) --first;
        int end = k;
        while (end < sequence.segments() && sequence.in_stance(leg, end) == state) ++end;
        EXPECT_EQ(run.first, first);
        const int standing_after = state && end == sequence.segments() ? ContactSequence::kStandAfterEndSegments : 0;
        EXPECT_EQ(run.length, end - first + standing_after);
      }
    }
  }
}

TEST(ContactSequence, TheSchedulerWalksThroughItOnceAndThenStands) {
  GaitScheduler scheduler(0.03);
  scheduler.play(std::make_shared<const ContactSequence>(moonwalk()));
  ASSERT_TRUE(scheduler.playing());
  // 6.5 segments in: section 3 (segments 5..9), FR in the second segment of its swing run 4..9
  scheduler.advance(6.5 * 0.03);
  const LegPhase fr = scheduler.leg_phase(0);
  EXPECT_FALSE(fr.stance);
  EXPECT_NEAR(fr.swing_phase, (6.5 - 4.0) / 7.0, 1e-9);  // segments 4..10 are all FR swing (sections 2-4)
  EXPECT_NEAR(fr.swing_duration_s, 7 * 0.03, 1e-12);
  const LegPhase fl = scheduler.leg_phase(1);
  EXPECT_TRUE(fl.stance);
  EXPECT_NEAR(fl.stance_phase, 1.5 / 5.0, 1e-9);
  // the MPC sees the schedule ahead, then standing past the end
  const auto table = scheduler.horizon_contacts<10>();
  EXPECT_FALSE(table[0][0]);
  EXPECT_TRUE(table[0][1]);
  EXPECT_FALSE(table[4][1]);  // segment 10: all in the air
  EXPECT_FALSE(scheduler.sequence_finished());
  scheduler.advance(20 * 0.03);
  EXPECT_TRUE(scheduler.sequence_finished());
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) EXPECT_TRUE(scheduler.leg_phase(leg).stance);
  // a pattern ends the sequence
  scheduler.set_pattern(*gait_pattern(kStandGaitId));
  EXPECT_FALSE(scheduler.playing());
}

}  // namespace
}  // namespace cerebellum
