#include "cli/cmd_options.hpp"

#include "cli/option_number.hpp"
#include "control/locomotion/gait_table.hpp"
#include "modes/command_ranges.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace cerebellum {
namespace {

constexpr int kDefaultWalkGait = kSlowTrotGaitId;
constexpr double kWalkStepHeightM = 0.05;    // what `walk` sends when --step-height is not given
constexpr double kMaxDurationS = 2147483.0;  // int32 milliseconds

const std::map<std::string, std::set<std::string>>& verb_options() {
  static const std::map<std::string, std::set<std::string>> options{
      {"stand", {}},
      {"lie", {}},
      {"damp", {}},
      {"pose", {"--roll", "--pitch", "--yaw", "--height", "--duration"}},
      {"height", {"--duration"}},
      {"walk", {"--vx", "--vy", "--yaw-rate", "--gait", "--step-height", "--duration"}},
      {"raw",
       {"--mode", "--gait", "--contact", "--value", "--duration", "--vel", "--rpy", "--pos", "--acc", "--ctrl-point",
        "--foot-pose", "--step-height"}},
  };
  return options;
}

std::string format(double value) {
  std::ostringstream out;
  out << std::setprecision(10) << value;
  return out.str();
}

std::string join(const std::set<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

// "[lower, upper]"
std::string interval(const Range& range) {
  std::string text = "[";
  text += format(range.lower);
  text += ", ";
  text += format(range.upper);
  return text + "]";
}

// the gait ids `walk` accepts: the stepping gaits of the gait table, e.g. "2, 3, 4"
std::string walking_gait_ids() {
  std::string ids;
  for (const GaitSpec& gait : kGaitTable) {
    if (gait_steps(gait)) ids += (ids.empty() ? "" : ", ") + std::to_string(gait.id);
  }
  return ids;
}

std::set<std::string> all_of(std::set<std::string> options, const std::set<std::string>& flags) {
  options.insert(flags.begin(), flags.end());
  return options;
}

// the option values of one command line, checked against the accepted option names
class OptionValues {
 public:
  // accepted: options with a value; flags: options without one
  OptionValues(std::string context, const std::vector<std::string>& args, std::size_t first,
               const std::set<std::string>& accepted, bool& help, const std::set<std::string>& flags = {})
      : context_(std::move(context)) {
    for (std::size_t i = first; i < args.size(); ++i) {
      const std::string& arg = args[i];
      if (arg == "--help" || arg == "-h") {
        help = true;
        continue;
      }
      if (flags.count(arg) != 0) {
        values_[arg] = "";
        continue;
      }
      if (arg.rfind("--", 0) != 0 || accepted.count(arg) == 0) {
        fail("unknown " + std::string(arg.rfind("--", 0) == 0 ? "option" : "argument") + " '" + arg +
             "' (accepted: " + (accepted.empty() && flags.empty() ? std::string("none") : join(all_of(accepted, flags))) + ")");
      }
      if (i + 1 >= args.size()) fail(arg + " needs a value");
      values_[arg] = args[++i];
    }
  }

  bool has(const std::string& option) const { return values_.count(option) != 0; }

  double number(const std::string& option, Range range, const char* unit, double fallback) const {
    if (!has(option)) return fallback;
    const std::string& text = values_.at(option);
    const std::optional<double> value = finite_number(text);
    if (!value || *value < range.lower || *value > range.upper) {
      fail(option + " must be a number in [" + format(range.lower) + ", " + format(range.upper) + "]" + unit +
           ", got '" + text + "'");
    }
    return *value;
  }

  long integer(const std::string& option, long lower, long upper, long fallback) const {
    if (!has(option)) return fallback;
    const std::string& text = values_.at(option);
    const std::optional<double> value = finite_number(text);
    if (!value || *value != std::floor(*value) || *value < lower || *value > upper) {
      fail(option + " must be an integer in [" + std::to_string(lower) + ", " + std::to_string(upper) + "], got '" +
           text + "'");
    }
    return static_cast<long>(*value);
  }

  template <std::size_t N>
  void numbers(const std::string& option, float (&out)[N]) const {
    if (!has(option)) return;
    const std::string& text = values_.at(option);
    std::stringstream items(text);
    std::string item;
    std::size_t count = 0;
    while (std::getline(items, item, ',')) {
      const std::optional<double> value = finite_number(item);
      if (!value || count >= N || std::abs(*value) > 1e6) {
        count = N + 1;
        break;
      }
      out[count++] = static_cast<float>(*value);
    }
    if (count != N) {
      fail(option + " must be " + std::to_string(N) + " comma-separated numbers in [-1e6, 1e6], got '" + text + "'");
    }
  }

  [[noreturn]] void fail(const std::string& what) const { throw std::invalid_argument(context_ + ": " + what); }

 private:
  std::string context_;
  std::map<std::string, std::string> values_;
};

// the verb's options plus those of every verb
std::set<std::string> accepted_for(const std::string& verb) {
  std::set<std::string> accepted = verb_options().at(verb);
  accepted.insert({"--timeout", "--hold", "--ttl"});
  return accepted;
}

std::int32_t duration_ms(const OptionValues& values, double lower_s, double fallback_s) {
  return static_cast<std::int32_t>(
      std::lround(values.number("--duration", {lower_s, kMaxDurationS}, " s", fallback_s) * 1000.0));
}

void set_mode(robot_control_cmd_lcmt& command, int mode, int gait_id) {
  command.mode = static_cast<std::int8_t>(mode);
  command.gait_id = static_cast<std::int8_t>(gait_id);
  command.contact = 0x0F;
}

void build_walk(const OptionValues& values, robot_control_cmd_lcmt& command) {
  const long gait = values.integer("--gait", 0, 127, kDefaultWalkGait);
  const GaitSpec* limits = find_gait(static_cast<int>(gait));
  if (limits == nullptr || !gait_steps(*limits)) {
    values.fail("--gait must be one of " + walking_gait_ids() + ", got " + std::to_string(gait));
  }
  const std::string context = " (gait " + std::to_string(gait) + ")";
  set_mode(command, static_cast<int>(ModeId::Locomotion), static_cast<int>(gait));
  const auto& min = limits->velocity_min;
  const auto& max = limits->velocity_max;
  command.vel_des[0] = static_cast<float>(values.number("--vx", {min[0], max[0]}, (" m/s" + context).c_str(), 0.0));
  command.vel_des[1] = static_cast<float>(values.number("--vy", {min[1], max[1]}, (" m/s" + context).c_str(), 0.0));
  command.vel_des[2] =
      static_cast<float>(values.number("--yaw-rate", {min[2], max[2]}, (" rad/s" + context).c_str(), 0.0));
  const double step_height_m = values.number("--step-height", kStepHeightRange, " m", kWalkStepHeightM);
  command.step_height[0] = command.step_height[1] = static_cast<float>(step_height_m);
  command.duration = duration_ms(values, 0.0, 0.0);
}

void build_raw(const OptionValues& values, robot_control_cmd_lcmt& command) {
  if (!values.has("--mode")) values.fail("--mode is required (an integer in [-128, 127])");
  command.mode = static_cast<std::int8_t>(values.integer("--mode", -128, 127, 0));
  command.gait_id = static_cast<std::int8_t>(values.integer("--gait", -128, 127, 0));
  command.contact = static_cast<std::int8_t>(values.integer("--contact", -128, 127, 0x0F));
  command.value = static_cast<std::int32_t>(values.integer("--value", -2147483647L - 1, 2147483647L, 0));
  command.duration = duration_ms(values, 0.0, 0.0);
  values.numbers("--vel", command.vel_des);
  values.numbers("--rpy", command.rpy_des);
  values.numbers("--pos", command.pos_des);
  values.numbers("--acc", command.acc_des);
  values.numbers("--ctrl-point", command.ctrl_point);
  values.numbers("--foot-pose", command.foot_pose);
  values.numbers("--step-height", command.step_height);
}

}  // namespace

std::string cmd_usage() {
  const QpStandRanges pose;
  const PoseControlRanges height;
  const GaitSpec& default_gait = *find_gait(kDefaultWalkGait);
  return "usage: cerebellum cmd <verb> [options]\n"
         "  sends one robot_control_cmd, waits for the mode (order_process_bar >= 95), then keeps the heartbeat\n"
         "verbs:\n"
         "  stand                  recovery stand (12, 0)\n"
         "  lie                    active lie-down to the lying pose (7, 1)\n"
         "  damp                   passive lie-down, joint damping (7, 0)\n"
         "  pose [--roll R] [--pitch P] [--yaw Y] [--height H] [--duration S]\n"
         "                         QP stand (3, 0): roll in " +
         interval(pose.roll) + " rad and pitch in " + interval(pose.pitch) +
         " rad absolute (+pitch raises the head),\n"
         "                         yaw in " +
         interval(pose.yaw) + " rad relative, height in " + interval(pose.height) + " m (default " +
         format(pose.default_height_m) +
         ")\n"
         "  height H [--duration S]\n"
         "                         body height H in " +
         interval(height.height) +
         " m (pose control 21, 5) over S s (default 1)\n"
         "  walk [--vx V] [--vy V] [--yaw-rate W] [--gait N] [--step-height H] [--duration S]\n"
         "                         locomotion (11, N), N in " +
         walking_gait_ids() + " (default " + std::to_string(default_gait.id) + ", " + default_gait.name +
         ");\n"
         "                         velocities within the gait's limits (docs/highlevel.md); step height in\n"
         "                         " +
         interval(kStepHeightRange) + " m (default " + format(kWalkStepHeightM) +
         "); S = 0 (default) walks until replaced\n"
         "  raw --mode M [--gait G] [--contact C] [--value V] [--duration S] [--vel x,y,yaw] [--rpy r,p,y]\n"
         "      [--pos x,y,z] [--acc a1,...,a6] [--ctrl-point x,y,z] [--foot-pose p1,...,p6] [--step-height f,r]\n"
         "                         any command; M, G, C in [-128, 127]\n"
         "options of every verb:\n"
         "  --duration S  the command's duration in seconds (0: runs until replaced; ms resolution)\n"
         "  --timeout S   wait at most S s for the mode (default 10)\n"
         "  --hold S      keep the heartbeat S s after that (default: until Ctrl-C; 0 for lie and damp)\n"
         "  --ttl N       multicast ttl of the LCM urls, 0..255 (default 255; 0 keeps packets on this host)\n"
         "Without a heartbeat the MC goes to PureDamper after 0.5 s (get-down protection).\n"
         "Exit status: 0 done, 1 refused (BAN_TRANS), timed out or no transport, 2 bad usage.\n";
}

std::string status_usage() {
  return "usage: cerebellum status [--count N] [--rate HZ] [--timeout S] [--ttl N] [--diagnostics]\n"
         "  prints robot_control_response and global_to_robot (odometry) until Ctrl-C\n"
         "  --diagnostics also the MC's own figures once a second (mc_diagnostics): the loop's period\n"
         "                p50 / p99 / max, and on a real robot its link: the state's age p50 / p99 / max,\n"
         "                link losses, refused states, late frames\n"
         "  --count N     stop after N lines (N >= 1)\n"
         "  --rate HZ     lines per second, in [0.1, 50] (default 5)\n"
         "  --timeout S   give up when no response arrives within S s (default 3)\n"
         "  --ttl N       multicast ttl of the LCM urls, 0..255 (default 255)\n";
}

CmdOptions parse_cmd_options(const std::vector<std::string>& args) {
  CmdOptions options;
  std::set<std::string> verbs;
  for (const auto& [verb, accepted] : verb_options()) verbs.insert(verb);
  if (args.empty()) throw std::invalid_argument("cmd: missing verb (accepted: " + join(verbs) + ")\n" + cmd_usage());
  if (args[0] == "--help" || args[0] == "-h") {
    options.help = true;
    return options;
  }
  options.verb = args[0];
  if (verbs.count(options.verb) == 0) {
    throw std::invalid_argument("cmd: unknown verb '" + options.verb + "' (accepted: " + join(verbs) + ")\n" +
                                cmd_usage());
  }
  const std::string context = "cmd " + options.verb;
  std::size_t first_option = 1;
  std::string height_text;
  if (options.verb == "height") {
    if (args.size() < 2 || args[1].rfind("--", 0) == 0) {
      throw std::invalid_argument(context + ": needs the height H in m, e.g. 'cmd height 0.22'");
    }
    height_text = args[1];
    first_option = 2;
  }
  const OptionValues values(context, args, first_option, accepted_for(options.verb), options.help);
  if (options.help) return options;

  options.timeout_s = values.number("--timeout", {0.1, 3600.0}, " s", 10.0);
  if (values.has("--hold")) options.hold_s = values.number("--hold", {0.0, 1e6}, " s", 0.0);
  options.ttl = static_cast<int>(values.integer("--ttl", 0, 255, 255));

  robot_control_cmd_lcmt& command = options.command;
  if (options.verb == "stand") {
    set_mode(command, static_cast<int>(ModeId::RecoveryStand), 0);
  } else if (options.verb == "lie" || options.verb == "damp") {
    set_mode(command, static_cast<int>(ModeId::PureDamper), options.verb == "lie" ? 1 : 0);
    if (!options.hold_s) options.hold_s = 0.0;
  } else if (options.verb == "pose") {
    const QpStandRanges ranges;
    set_mode(command, static_cast<int>(ModeId::QpStand), 0);
    command.rpy_des[0] = static_cast<float>(values.number("--roll", ranges.roll, " rad", 0.0));
    command.rpy_des[1] = static_cast<float>(values.number("--pitch", ranges.pitch, " rad", 0.0));
    command.rpy_des[2] = static_cast<float>(values.number("--yaw", ranges.yaw, " rad", 0.0));
    command.pos_des[2] = static_cast<float>(values.number("--height", ranges.height, " m", ranges.default_height_m));
    command.duration = duration_ms(values, 0.0, 0.0);
  } else if (options.verb == "height") {
    const Range range = PoseControlRanges{}.height;
    const std::optional<double> height_m = finite_number(height_text);
    if (!height_m || *height_m < range.lower || *height_m > range.upper) {
      values.fail("H must be a number in " + interval(range) + " m, got '" + height_text + "'");
    }
    set_mode(command, static_cast<int>(ModeId::PoseControl), 5);
    command.pos_des[2] = static_cast<float>(*height_m);
    command.duration = duration_ms(values, 0.001, 1.0);
  } else if (options.verb == "walk") {
    build_walk(values, command);
  } else {
    build_raw(values, command);
  }
  return options;
}

StatusOptions parse_status_options(const std::vector<std::string>& args) {
  StatusOptions options;
  const OptionValues values("status", args, 0, {"--count", "--rate", "--timeout", "--ttl"}, options.help,
                            {"--diagnostics"});
  if (options.help) return options;
  options.diagnostics = values.has("--diagnostics");
  if (values.has("--count")) options.count = values.integer("--count", 1, 1000000000L, 1);
  options.rate_hz = values.number("--rate", {0.1, 50.0}, " Hz", 5.0);
  options.timeout_s = values.number("--timeout", {0.1, 3600.0}, " s", 3.0);
  options.ttl = static_cast<int>(values.integer("--ttl", 0, 255, 255));
  return options;
}

}  // namespace cerebellum
