// Command-line options of `cerebellum sim`.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "backend/terrain.hpp"

namespace cerebellum {

struct SimOptions {
  double speed = 1.0;        // real-time factor; <= 0 means as fast as possible ("max")
  double duration_s = -1.0;  // < 0: until SIGINT/SIGTERM
  std::string config_path;   // empty: built-in defaults
  std::optional<unsigned> seed;
  std::string faults_path;  // a fault scenario file (docs/safety.md); empty: none
  std::optional<TerrainSpec> terrain;  // the ground (docs/terrain.md); over the configuration's
  bool help = false;
  // tools (docs/tools.md)
  bool viewer = false;
  std::string viewer_screenshot_path;  // the viewer's last frame, as .png
  std::string record_path;             // headless video of the run
  double record_fps = 30.0;
  int record_width = 1280;
  int record_height = 720;
  // --progress-to: where the video's rendering bar is drawn when the run ends (a terminal, while
  // the sim's own output goes to a log); empty: the standard output
  std::string progress_path;
  std::string telemetry_path;  // CSV
  double telemetry_rate_hz = 100.0;
};

// throws std::invalid_argument naming the option and the accepted values
SimOptions parse_sim_options(const std::vector<std::string>& args);
std::string sim_usage();

}  // namespace cerebellum
