#include "io/common/rate_limited_log.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "io/common/count_report.hpp"

namespace cerebellum {
namespace {

// the lines written to a temporary file
class CapturedLog {
 public:
  CapturedLog() : file_(std::tmpfile()) {}
  ~CapturedLog() { std::fclose(file_); }
  std::FILE* file() { return file_; }
  std::string text() {
    std::fflush(file_);
    std::rewind(file_);
    std::string text;
    for (int c = std::fgetc(file_); c != EOF; c = std::fgetc(file_)) text += static_cast<char>(c);
    return text;
  }

 private:
  std::FILE* file_;
};

int count_lines(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n';
  return lines;
}

TEST(RateLimitedLog, AFloodWritesAtMostTheLimitPerSecondAndOneSummaryForTheRest) {
  CapturedLog captured;
  RateLimitedLog log(captured.file(), "highlevel", "refusals", 5);
  for (int i = 0; i < 1000; ++i) log.line(10.0 + i * 1e-4, "refused " + std::to_string(i));
  log.tick(11.5);
  const std::string text = captured.text();
  EXPECT_EQ(count_lines(text), 6) << text;
  EXPECT_NE(text.find("highlevel: refused 0\n"), std::string::npos);
  EXPECT_NE(text.find("highlevel: refused 4\n"), std::string::npos);
  EXPECT_EQ(text.find("refused 5\n"), std::string::npos);
  EXPECT_NE(text.find("highlevel: 995 more refusals in the last second not shown"), std::string::npos) << text;
  EXPECT_EQ(log.written(), 5u);
  EXPECT_EQ(log.suppressed(), 995u);
}

TEST(RateLimitedLog, ANewSecondAllowsNewLines) {
  CapturedLog captured;
  RateLimitedLog log(captured.file(), "x", "lines", 1);
  log.line(0.0, "a");
  log.line(0.5, "b");
  log.line(1.0, "c");
  const std::string text = captured.text();
  EXPECT_EQ(text, "x: a\nx: 1 more lines in the last second not shown\nx: c\n");
}

TEST(CountReport, ListsOnlyTheNonZeroCountsCommaSeparated) {
  std::string text;
  append_count(text, 0, "truncated");
  append_count(text, 3, "oversized");
  append_count(text, 12, "with NaN/Inf");
  EXPECT_EQ(text, "3 oversized, 12 with NaN/Inf");
}

TEST(EveryPeriod, IsDueOncePerPeriodCountedFromTheLastTimeItWasDue) {
  EveryPeriod period(100.0, 1.0);
  EXPECT_FALSE(period.due(100.5));
  EXPECT_TRUE(period.due(101.2));
  EXPECT_FALSE(period.due(102.0));
  EXPECT_TRUE(period.due(102.2));
}

}  // namespace
}  // namespace cerebellum
