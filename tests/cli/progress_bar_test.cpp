// The progress line: the bar, the count, the time left from the pace so far (given, never read
// from a clock), and silence when the output is not a terminal.
#include "cli/progress_bar.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace cerebellum {
namespace {

TEST(ProgressBar, TheTimeLeftComesFromThePaceSoFar) {
  // 10 of 40 done in 30 s: 3 s each, 30 to go -> 90 s
  EXPECT_EQ(progress_line("sweep", 10, 40, 30.0, ""),
            "sweep [#######.......................] 10/40, 1 min 30 s left");
}

TEST(ProgressBar, NoTimeLeftBeforeTheFirstItemOrAfterTheLast) {
  EXPECT_EQ(progress_line("sweep", 0, 4, 12.0, ""), "sweep [..............................] 0/4");
  EXPECT_EQ(progress_line("sweep", 4, 4, 12.0, "1 crashed"), "sweep [##############################] 4/4, 1 crashed");
}

TEST(ProgressBar, DurationsReadInTheirLargestUnits) {
  EXPECT_EQ(duration_text(12.4), "12 s");
  EXPECT_EQ(duration_text(200), "3 min 20 s");
  EXPECT_EQ(duration_text(3 * 3600 + 5 * 60 + 9), "3 h 05 min");
  EXPECT_EQ(duration_text(-1), "0 s");
}

TEST(ProgressBar, NothingIsDrawnIntoAFile) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  ProgressBar bar(file, "sweep");
  bar.update(1, 2, 1.0);
  bar.finish();
  EXPECT_EQ(std::ftell(file), 0);
  std::fclose(file);
}

}  // namespace
}  // namespace cerebellum
