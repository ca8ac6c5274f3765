// The tools end to end through the cerebellum program: the headless recorder's video, the
// telemetry CSV and its plots, the viewer under a virtual display, and their errors.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "observers/record_telemetry.hpp"
#include "viz/tool_test_support.hpp"

namespace cerebellum {
namespace {

using test::quoted;
using test::run_command;

const std::string kProgram = CEREBELLUM_EXECUTABLE;

std::string sim(const std::string& arguments) { return quoted(kProgram) + " sim " + arguments; }

// "width,height,frames" of the first video stream
std::string probe_video(const std::string& path) {
  return run_command(
             "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
             "stream=width,height,nb_read_frames -of csv=p=0 " +
             quoted(path))
      .output;
}

std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::stringstream in(test::read_file(path));
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream fields_in(line);
    std::string field;
    while (std::getline(fields_in, field, ',')) fields.push_back(field);
    rows.push_back(fields);
  }
  return rows;
}

TEST(ToolsCli, LockstepRecordingRendersEveryFrameOfADecodableVideo) {
  test::ScratchDir dir;
  const std::string video = dir / "stand.mp4";
  const auto run =
      run_command(sim("--speed max --duration 2 --record " + quoted(video) + " --record-fps 10 --record-size 320x240"));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(
      run.output.find("video: 20 frames at 10 fps (0 repeated because rendering fell behind) written to " + video),
      std::string::npos)
      << run.output;
  EXPECT_EQ(probe_video(video), "320,240,20\n");
  // the first frame shows the scene (floor, robot, text), not an empty buffer
  const auto first = test::decode_gray_frame(video, 0, 320, 240, dir);
  ASSERT_EQ(first.size(), 320u * 240u);
  EXPECT_GT(test::variance(first), 100.0);
}

TEST(ToolsCli, PacedRecordingKeepsOneFramePerPeriodOfRobotTime) {
  test::ScratchDir dir;
  const std::string video = dir / "paced.mkv";
  const auto run =
      run_command(sim("--speed 2 --duration 1 --record " + quoted(video) + " --record-fps 20 --record-size 320x240"));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  // however many frames rendering skipped and repeated, the count and so the timing is exact
  EXPECT_TRUE(std::regex_search(run.output, std::regex("video: 20 frames at 20 fps \\([0-9]+ repeated"))) << run.output;
  EXPECT_EQ(probe_video(video), "320,240,20\n");
}

TEST(ToolsCli, TelemetryRowsAtTheRateAndPlotsFromThem) {
  test::ScratchDir dir;
  const std::string csv = dir / "stand.csv";
  // the MC stands the robot up by itself (the default lies, as after power-on)
  const std::string config = dir / "stand.yaml";
  std::ofstream(config) << "mc:\n  startup: stand\n";
  const auto run = run_command(sim("--speed max --duration 3 --config " + quoted(config) + " --telemetry " +
                                   quoted(csv) + " --telemetry-rate 50"));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("telemetry: 150 rows written to " + csv), std::string::npos) << run.output;

  const auto rows = read_csv(csv);
  ASSERT_EQ(rows.size(), 151u);
  std::string header;
  for (const auto& name : rows[0]) header += (header.empty() ? "" : ",") + name;
  EXPECT_EQ(header, telemetry_header());
  for (std::size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), rows[0].size()) << "row " << i;
    EXPECT_NEAR(std::stod(rows[i][0]), 0.02 * static_cast<double>(i - 1), 1e-9) << "row " << i;
  }
  // after the recovery stand the trunk stands, and the estimate agrees with the truth
  const auto& last = rows.back();
  const auto column = [&](const std::string& name) {
    for (std::size_t i = 0; i < rows[0].size(); ++i) {
      if (rows[0][i] == name) return std::stod(last[i]);
    }
    ADD_FAILURE() << "no column " << name;
    return 0.0;
  };
  EXPECT_GT(column("truth_z_m"), 0.2);
  EXPECT_LT(column("truth_z_m"), 0.3);
  EXPECT_NEAR(column("est_height_m"), column("truth_z_m"), 0.02);
  EXPECT_GT(column("tau_fr_knee_nm") * column("tau_fr_knee_nm"), 0.1);
  EXPECT_GT(column("temp_fr_knee_c"), 20.0);

  const std::string plots = dir / "plots";
  const auto plotted = run_command("/usr/bin/python3 " + quoted(CEREBELLUM_SOURCE_DIR "/scripts/plot_telemetry.py") +
                                   " " + quoted(csv) + " --out " + quoted(plots));
  ASSERT_EQ(plotted.exit_code, 0) << plotted.output;
  for (const char* name :
       {"body_height.png", "velocity_tracking.png", "joint_torques.png", "temperatures.png", "battery.png"}) {
    const std::string png = test::read_file(plots + "/" + name);
    EXPECT_GT(png.size(), 10000u) << name;
    EXPECT_EQ(png.substr(0, 8), "\x89PNG\r\n\x1a\n") << name;
  }
}

TEST(ToolsCli, PlotScriptRefusesAFileThatIsNotTelemetry) {
  test::ScratchDir dir;
  const std::string csv = dir / "other.csv";
  std::ofstream(csv) << "a,b\n1,2\n";
  const auto plotted = run_command("/usr/bin/python3 " + quoted(CEREBELLUM_SOURCE_DIR "/scripts/plot_telemetry.py") +
                                   " " + quoted(csv) + " --out " + quoted(dir / "plots"));
  EXPECT_EQ(plotted.exit_code, 1);
  EXPECT_NE(plotted.output.find("not a cerebellum telemetry file (no time_s column)"), std::string::npos)
      << plotted.output;
}

TEST(ToolsCli, ViewerOnAVirtualDisplaySavesANonBlankFrame) {
  ASSERT_TRUE(test::on_path("xvfb-run")) << "xvfb-run missing: scripts/install_deps.sh installs xvfb and xauth";
  test::ScratchDir dir;
  const std::string shot = dir / "viewer.png";
  const auto run = run_command("xvfb-run -a -n 90 -s '-screen 0 1280x1024x24' " +
                               sim("--viewer --speed max --duration 1 --viewer-screenshot " + quoted(shot)));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("viewer: last frame saved to " + shot), std::string::npos) << run.output;
  EXPECT_EQ(probe_video(shot), "1280,800,1\n");
  const auto frame = test::decode_gray_frame(shot, 0, 1280, 800, dir);
  ASSERT_EQ(frame.size(), 1280u * 800u);
  EXPECT_GT(test::variance(frame), 100.0);
}

TEST(ToolsCli, ViewerWithoutADisplaySaysHowToGetOne) {
  const auto run = run_command("env -u DISPLAY -u WAYLAND_DISPLAY " + sim("--viewer --duration 0.1"));
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.output.find("viewer: no display to open a window on"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("xvfb-run -a cerebellum sim --viewer"), std::string::npos) << run.output;
}

TEST(ToolsCli, RecorderWithoutFfmpegFailsBeforeTheRun) {
  test::ScratchDir dir;
  const auto run =
      run_command("env PATH=/nonexistent-directory " + sim("--duration 0.1 --record " + quoted(dir / "a.mp4")));
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.output.find("cerebellum sim: ffmpeg not found on PATH (Debian package: ffmpeg)"), std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find("cerebellum ready"), std::string::npos) << run.output;
}

TEST(ToolsCli, BadToolOptionExitsWithTwoAndNamesTheRule) {
  const auto run = run_command(sim("--record a.mp4 --record-size 321x240"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("--record-size: must be WxH with even integers"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace cerebellum
