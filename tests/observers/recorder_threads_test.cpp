// The recorders' own threads beside a running loop (the ThreadSanitizer stage's subject): the
// telemetry writer and the console reporter take every record the loop hands them, in order.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

#include "observers/console_reporter.hpp"
#include "observers/record_telemetry.hpp"
#include "loop/simulated_robot.hpp"

namespace cerebellum {
namespace {

TEST(RecorderThreads, TheTelemetryWriterWritesARowForEveryDueCycleWhileTheLoopRuns) {
  const std::string path = ::testing::TempDir() + "recorder_threads_" + std::to_string(::getpid()) + ".csv";
  Mc mc = make_simulated_mc(default_config());
  TelemetryRecorder recorder(path, 100.0, mc.simulation());
  mc.loop().add_observer(recorder);
  for (int i = 0; i < 500; ++i) mc.loop().tick();  // 1 s of robot time at 100 rows a second
  const TelemetryResult result = recorder.finish();
  EXPECT_TRUE(result.ok);
  EXPECT_EQ(result.dropped, 0u);
  EXPECT_EQ(result.rows, 100u);
  std::ifstream in(path);
  int lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  EXPECT_EQ(lines, 101) << "the header and one line per row";
  std::remove(path.c_str());
}

TEST(RecorderThreads, TheConsoleReporterPrintsOnceASecondOfRobotTime) {
  std::FILE* out = std::tmpfile();
  {
    Mc mc = make_simulated_mc(default_config());
    ConsoleReporter reporter(out, 1.0);
    mc.loop().add_observer(reporter);
    for (int i = 0; i < 1500; ++i) mc.loop().tick();  // 3 s
    reporter.finish();
  }
  std::rewind(out);
  int reports = 0;
  for (char line[512]; std::fgets(line, sizeof line, out) != nullptr;) reports += line[0] == 't' ? 1 : 0;
  std::fclose(out);
  EXPECT_EQ(reports, 3);
}

}  // namespace
}  // namespace cerebellum
