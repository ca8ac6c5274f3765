// Finding the per-port log files of a prefix, and counting the events liblcm wrote to one.
#include "cli/log_replay.hpp"

#include <gtest/gtest.h>
#include <lcm/eventlog.h>

#include <fstream>
#include <stdexcept>

#include "viz/tool_test_support.hpp"

namespace cerebellum {
namespace {

void touch(const std::string& path) { std::ofstream(path) << ""; }

std::string error_of_find(const std::string& prefix) {
  try {
    find_port_logs(prefix, {7667, 7669, 7670, 7671});
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(PortLogs, ListsTheExistingFilesOfAPrefixInPortOrder) {
  test::ScratchDir dir;
  touch(dir / "run.7671.lcmlog");
  touch(dir / "run.7667.lcmlog");
  touch(dir / "other.7669.lcmlog");
  const auto logs = find_port_logs(dir / "run", {7667, 7669, 7670, 7671});
  ASSERT_EQ(logs.size(), 2u);
  EXPECT_EQ(logs[0].port, 7667);
  EXPECT_EQ(logs[0].path, dir / "run.7667.lcmlog");
  EXPECT_EQ(logs[1].port, 7671);
  // a port filter leaves the others out
  const auto only = find_port_logs(dir / "run", {7671});
  ASSERT_EQ(only.size(), 1u);
  EXPECT_EQ(only[0].port, 7671);
}

TEST(PortLogs, TakesOneNamedFileAndRefusesNamesWithoutAnInterfacePort) {
  test::ScratchDir dir;
  touch(dir / "run.7670.lcmlog");
  touch(dir / "run.1234.lcmlog");
  const auto one = find_port_logs(dir / "run.7670.lcmlog", {7667});
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].port, 7670);
  EXPECT_NE(error_of_find(dir / "run.1234.lcmlog").find("cannot tell the port"), std::string::npos);
  EXPECT_NE(error_of_find(dir / "missing.7670.lcmlog").find("no such log file"), std::string::npos);
  EXPECT_NE(error_of_find(dir / "nothing").find("no log files"), std::string::npos);
}

TEST(PortLogs, CountsTheEventsLiblcmWrote) {
  test::ScratchDir dir;
  const std::string path = dir / "count.7667.lcmlog";
  lcm_eventlog_t* log = lcm_eventlog_create(path.c_str(), "w");
  ASSERT_NE(log, nullptr);
  char channel[] = "spi_data";
  unsigned char payload[16] = {1, 2, 3};
  for (int i = 0; i < 5; ++i) {
    lcm_eventlog_event_t event{};
    event.eventnum = i;
    event.timestamp = 1000 * i;
    event.channellen = 8;
    event.datalen = sizeof payload;
    event.channel = channel;
    event.data = payload;
    ASSERT_EQ(lcm_eventlog_write_event(log, &event), 0);
  }
  lcm_eventlog_destroy(log);
  EXPECT_EQ(count_log_events(path), 5u);
  EXPECT_THROW(count_log_events(dir / "absent.lcmlog"), std::runtime_error);
}

}  // namespace
}  // namespace cerebellum
