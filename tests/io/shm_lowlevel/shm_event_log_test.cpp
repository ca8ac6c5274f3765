#include "io/shm_lowlevel/shm_event_log.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace cerebellum {
namespace {

std::string text_of(std::FILE* file) {
  std::fflush(file);
  std::rewind(file);
  std::string text;
  for (int c = std::fgetc(file); c != EOF; c = std::fgetc(file)) text += static_cast<char>(c);
  return text;
}

int count_of(const std::string& text, const std::string& what) {
  int count = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++count;
  return count;
}

// a client's NaN kp in `count` frames, one a millisecond from t = 0
void post_rejected_frames(ShmEventLog& log, int count) {
  for (int i = 0; i < count; ++i) {
    ShmEvent event;
    event.kind = ShmEventKind::FrameRejected;
    event.time_s = i * 0.001;
    event.check.fault = ShmCommandFault::NonFinite;
    event.check.field = ShmCommandField::Kp;
    event.check.value = std::nan("");
    log.post(event);
  }
}

// a client writing a NaN frame every millisecond must not write a log line every millisecond
TEST(ShmEventLog, AFloodOfRejectedFramesPrintsAFewLinesAndCountsTheRest) {
  std::FILE* file = std::tmpfile();
  {
    ShmEventLog log(file);
    post_rejected_frames(log, 60);
    log.flush();
    const std::string text = text_of(file);
    EXPECT_EQ(count_of(text, "command frame rejected"), 5) << text;
    EXPECT_NE(text.find("cerebellum shm: t=0.000 s command frame rejected: FR abad kp = nan (not finite)"),
              std::string::npos)
        << text;
    EXPECT_EQ(log.client_lines_suppressed(), 55u);
  }
  std::fclose(file);
}

// a client whose frames are both rejected by the dozen and ignored (another source has the robot)
// still reads why it is ignored: the two kinds of line do not share one budget
TEST(ShmEventLog, TheLineThatAnotherSourceHasTheRobotIsPrintedThroughAFloodOfRejectedFrames) {
  std::FILE* file = std::tmpfile();
  {
    ShmEventLog log(file);
    post_rejected_frames(log, 40);
    ShmEvent refused;
    refused.kind = ShmEventKind::Refused;
    refused.time_s = 0.05;
    refused.holder = "the motor SDK client";
    log.post(refused);
    log.flush();
    const std::string text = text_of(file);
    EXPECT_EQ(count_of(text, "command frames ignored: the motor SDK client has the robot"), 1) << text;
    EXPECT_EQ(log.ignored_lines_written(), 1u);
  }
  std::fclose(file);
}

}  // namespace
}  // namespace cerebellum
