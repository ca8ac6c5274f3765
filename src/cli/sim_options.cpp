#include "cli/sim_options.hpp"

#include "cli/option_number.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cerebellum {
namespace {

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// WxH, both even (the video's 4:2:0 colour needs it), 16x16 to 3840x2160
void parse_size(const std::string& text, int& width, int& height) {
  const std::string accepted = "WxH with even integers, 16x16 to 3840x2160";
  const std::size_t x = text.find('x');
  if (x == std::string::npos) throw std::invalid_argument("--record-size: '" + text + "' is not " + accepted);
  const double w = option_number("--record-size", text.substr(0, x), accepted);
  const double h = option_number("--record-size", text.substr(x + 1), accepted);
  if (w != std::floor(w) || h != std::floor(h) || w < 16 || h < 16 || w > 3840 || h > 2160 ||
      static_cast<long>(w) % 2 != 0 || static_cast<long>(h) % 2 != 0) {
    throw std::invalid_argument("--record-size: must be " + accepted + ", got " + text);
  }
  width = static_cast<int>(w);
  height = static_cast<int>(h);
}

// options that only make sense with another one, and combinations that cannot run together
void check_tool_options(const SimOptions& options, const std::vector<std::string>& seen) {
  const auto given = [&](const char* name) { return std::find(seen.begin(), seen.end(), name) != seen.end(); };
  if (options.viewer && !options.record_path.empty()) {
    throw std::invalid_argument(
        "--viewer and --record cannot run together: record without the viewer "
        "(the recorder renders headlessly)");
  }
  if (given("--viewer-screenshot") && !options.viewer)
    throw std::invalid_argument("--viewer-screenshot needs --viewer");
  for (const char* option : {"--record-fps", "--record-size", "--progress-to"}) {
    if (given(option) && options.record_path.empty()) {
      throw std::invalid_argument(std::string(option) + " needs --record FILE.mp4");
    }
  }
  if (given("--telemetry-rate") && options.telemetry_path.empty()) {
    throw std::invalid_argument("--telemetry-rate needs --telemetry FILE.csv");
  }
}

}  // namespace

std::string sim_usage() {
  return "usage: cerebellum sim [--speed X|max] [--duration S] [--config FILE] [--seed N] [--faults FILE]\n"
         "                      [--terrain SPEC] [--viewer [--viewer-screenshot FILE.png]]\n"
         "                      [--record FILE.mp4 [--record-fps F] [--record-size WxH] [--progress-to FILE]]\n"
         "                      [--telemetry FILE.csv [--telemetry-rate HZ]]\n"
         "  --speed X     pace at X times real time (X > 0, default 1); 'max' runs lockstep at full speed\n"
         "  --duration S  stop after S seconds of robot time (S > 0); default: run until Ctrl-C\n"
         "  --config FILE YAML configuration (see docs/configuration.md)\n"
         "  --seed N      seed of the sensor noise (integer >= 0)\n"
         "  --faults FILE a fault scenario (YAML: faults at simulated times; docs/safety.md);\n"
         "                at run time: cerebellum fault --help\n"
         "  --terrain SPEC  the ground (docs/terrain.md): " + std::string(terrain_spec_forms()) + "\n"
         "  --viewer      live 3D window (needs a display): P pause, M slow motion, C follow,\n"
         "                ctrl+right drag push, Esc quit; the other keys drive the robot (docs/driving.md)\n"
         "  --viewer-screenshot FILE.png  save the viewer's last frame when the run ends\n"
         "  --record FILE.mp4  render the run headlessly into a video (ffmpeg); not with --viewer\n"
         "  --record-fps F     video frames per second of robot time (0 < F <= 240, default 30)\n"
         "  --record-size WxH  video size in pixels, even numbers, 16x16 to 3840x2160 (default 1280x720)\n"
         "  --progress-to FILE where the bar of the video's rendering after the run is drawn, when FILE\n"
         "                     is a terminal (e.g. /dev/tty while the output goes to a log; default: the output)\n"
         "  --telemetry FILE.csv  log time, mode, estimated and true velocity, height, torques, temperatures\n"
         "  --telemetry-rate HZ   rows per second of robot time (HZ > 0, default 100)\n";
}

SimOptions parse_sim_options(const std::vector<std::string>& args) {
  SimOptions options;
  std::vector<std::string> seen;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw std::invalid_argument(arg + " needs a value\n" + sim_usage());
      return args[++i];
    };
    if (arg == "--help" || arg == "-h") {
      options.help = true;
    } else if (arg == "--speed") {
      const std::string& text = value();
      if (text == "max") {
        options.speed = 0.0;
      } else {
        options.speed = option_number(arg, text, "a number > 0 or 'max'");
        if (options.speed <= 0.0) throw std::invalid_argument("--speed: must be > 0 or 'max', got " + text);
      }
    } else if (arg == "--duration") {
      const std::string& text = value();
      options.duration_s = option_number(arg, text, "a number of seconds > 0");
      if (options.duration_s <= 0.0) throw std::invalid_argument("--duration: must be > 0, got " + text);
    } else if (arg == "--config") {
      options.config_path = value();
    } else if (arg == "--seed") {
      const std::string& text = value();
      const double seed = option_number(arg, text, "an integer >= 0");
      if (seed < 0 || seed != std::floor(seed) || seed > 4294967295.0) {
        throw std::invalid_argument("--seed: must be an integer in [0, 4294967295], got " + text);
      }
      options.seed = static_cast<unsigned>(seed);
    } else if (arg == "--faults") {
      options.faults_path = value();
      if (options.faults_path.empty())
        throw std::invalid_argument("--faults: needs a scenario file such as faults.yaml");
    } else if (arg == "--terrain") {
      options.terrain = parse_terrain_spec(value());
    } else if (arg == "--viewer") {
      options.viewer = true;
    } else if (arg == "--viewer-screenshot") {
      options.viewer_screenshot_path = value();
      if (!ends_with(options.viewer_screenshot_path, ".png")) {
        throw std::invalid_argument("--viewer-screenshot: the file must end in .png, got '" +
                                    options.viewer_screenshot_path + "'");
      }
    } else if (arg == "--record") {
      options.record_path = value();
      if (options.record_path.empty()) throw std::invalid_argument("--record: needs a file name such as run.mp4");
    } else if (arg == "--record-fps") {
      const std::string& text = value();
      options.record_fps = option_number(arg, text, "a number of frames per second in (0, 240]");
      if (options.record_fps <= 0.0 || options.record_fps > 240.0) {
        throw std::invalid_argument("--record-fps: must be in (0, 240], got " + text);
      }
    } else if (arg == "--progress-to") {
      options.progress_path = value();
      if (options.progress_path.empty()) throw std::invalid_argument("--progress-to: needs a file such as /dev/tty");
    } else if (arg == "--record-size") {
      parse_size(value(), options.record_width, options.record_height);
    } else if (arg == "--telemetry") {
      options.telemetry_path = value();
      if (options.telemetry_path.empty()) throw std::invalid_argument("--telemetry: needs a file name such as run.csv");
    } else if (arg == "--telemetry-rate") {
      const std::string& text = value();
      options.telemetry_rate_hz = option_number(arg, text, "a rate in Hz > 0");
      if (options.telemetry_rate_hz <= 0.0)
        throw std::invalid_argument("--telemetry-rate: must be > 0 Hz, got " + text);
    } else {
      throw std::invalid_argument("unknown option '" + arg + "'\n" + sim_usage());
    }
    seen.push_back(arg);
  }
  check_tool_options(options, seen);
  return options;
}

}  // namespace cerebellum
