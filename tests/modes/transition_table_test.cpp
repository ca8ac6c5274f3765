// Every row of the mode table, legal and illegal.
#include "modes/transition_table.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>

namespace cerebellum {
namespace {

// the reference table, written out as data
const std::map<int, std::set<int>> kAllowed = {
    {0, {12, 21, 7, 15, 62, 0}},
    {3, {11, 7, 21, 12, 0, 3}},
    {7, {0, 12, 7, 15}},
    {9, {7, 12, 0, 11, 3}},
    {11, {12, 0, 7, 21, 3, 11, 16}},
    {12, {0, 3, 7, 9, 11, 12, 15, 16, 21, 22, 62, 64}},
    {15, {0, 7, 12}},
    {16, {12, 0, 3, 21, 11, 7}},
    {21, {12, 0, 7, 21, 3, 11, 62, 16, 64}},
    {22, {21, 7, 3, 12, 0, 11, 64}},
    {62, {12, 0, 7, 21, 3}},
    {64, {12, 0, 7, 16, 3, 21}},
};

TEST(TransitionTable, EveryPairMatchesTheReferenceTable) {
  int legal = 0;
  for (const auto& [from, unused_row] : kAllowed) {
    for (const auto& [to, unused_column] : kAllowed) {
      const bool expected = kAllowed.at(from).count(to) > 0;
      EXPECT_EQ(transition_allowed(static_cast<ModeId>(from), static_cast<ModeId>(to)), expected)
          << from << " -> " << to;
      legal += expected;
    }
  }
  EXPECT_EQ(legal, 6 + 6 + 4 + 5 + 7 + 12 + 3 + 6 + 9 + 7 + 5 + 6);
}

TEST(TransitionTable, KnownModesAreExactlyTheTablesRows) {
  for (int m = -5; m < 130; ++m) {
    EXPECT_EQ(is_known_mode(m), kAllowed.count(m) > 0) << m;
  }
}

TEST(TransitionTable, TheModeListHoldsExactlyTheTablesRowsEachOnce) {
  std::set<int> listed;
  for (const ModeInfo& info : kAllModes) {
    EXPECT_TRUE(listed.insert(static_cast<int>(info.id)).second) << static_cast<int>(info.id);
    EXPECT_EQ(find_mode(static_cast<int>(info.id)), &info);
  }
  std::set<int> reference;
  for (const auto& [mode, unused] : kAllowed) reference.insert(mode);
  EXPECT_EQ(listed, reference);
  EXPECT_EQ(kMaxModeId, *reference.rbegin());
}

}  // namespace
}  // namespace cerebellum
