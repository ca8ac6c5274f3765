#include "motions/user_gait_program.hpp"

#include "modes/commanded_pose.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "control/locomotion/foothold.hpp"
#include "control/locomotion/gait_table.hpp"
#include "core/joint_layout.hpp"
#include "modes/command_ranges.hpp"

namespace cerebellum {
namespace {

// each leg's landing x, y in the packed fields
Eigen::Vector2d landing_of(const HighLevelCommand& step, std::size_t leg) {
  switch (leg) {
    case 0: return {step.foot_pose[0], step.foot_pose[1]};
    case 1: return {step.foot_pose[2], step.foot_pose[3]};
    case 2: return {step.foot_pose[4], step.foot_pose[5]};
    default: return {step.ctrl_point[0], step.ctrl_point[1]};
  }
}

// swing height (m) of each leg from the two packed numbers: first leg's mm + 1000 * second leg's mm
std::array<double, kNumLegs> step_heights_of(const HighLevelCommand& step) {
  std::array<double, kNumLegs> heights{};
  for (std::size_t pair = 0; pair < 2; ++pair) {
    const long packed = std::lround(std::floor(std::max(0.0f, step.step_height[pair])));
    heights[2 * pair] = (packed % 1000) * 1e-3;
    heights[2 * pair + 1] = ((packed / 1000) % 1000) * 1e-3;
  }
  return heights;
}

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char text[160];
  std::snprintf(text, sizeof(text), pattern, a, b, c);
  return text;
}

}  // namespace

int max_flight_segments() {
  const GaitCycle pronk = find_gait(kPronkGaitId)->cycle;
  return pronk.period_segments - pronk.stance_segments;
}

std::string definition_problem(const UserGaitDefinition& definition) {
  long total = 0;
  int flight = 0;
  std::size_t flight_start = 0;
  for (std::size_t i = 0; i < definition.sections.size(); ++i) {
    const GaitSection& section = definition.sections[i];
    total += section.duration_units;
    const bool airborne = std::none_of(section.stance.begin(), section.stance.end(), [](bool down) { return down; });
    if (!airborne) {
      flight = 0;
      continue;
    }
    if (flight == 0) flight_start = i;
    flight += section.duration_units;
    if (flight > max_flight_segments()) {
      return "sections " + std::to_string(flight_start + 1) + ".." + std::to_string(i + 1) +
             " keep every foot off the ground for " + std::to_string(flight) + " units (" +
             format("%.0f ms", flight * kGaitSegmentS * 1e3) + "); the robot flies at most " +
             std::to_string(max_flight_segments()) + " units (" +
             format("%.0f ms", max_flight_segments() * kGaitSegmentS * 1e3) + ")";
    }
  }
  if (total * kGaitSegmentS > kMaxUserGaitS) {
    return "the sections last " + std::to_string(total) + " units (" + format("%.1f s", total * kGaitSegmentS) +
           "), more than " + format("%.0f s", kMaxUserGaitS);
  }
  return "";
}

std::string parameters_problem(const UserGaitParameters& parameters) {
  const FootholdConfig reach;
  double total_s = 0.0;
  for (std::size_t i = 0; i < parameters.steps.size(); ++i) {
    const HighLevelCommand& step = parameters.steps[i];
    const std::string where = "step " + std::to_string(i + 1) + ": ";
    if (step.mode != static_cast<int>(ModeId::Locomotion) || step.gait_id != kUserGaitId) {
      return where + "mode and gait_id must be 11 and 110 (a user gait step), found " + std::to_string(step.mode) +
             " and " + std::to_string(step.gait_id);
    }
    if (step.duration <= 0) return where + "duration must be > 0 ms, found " + std::to_string(step.duration);
    total_s += step.duration * 1e-3;
    for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
      const Eigen::Vector2d landing = landing_of(step, leg);
      if (std::abs(landing.x()) > reach.max_offset_forward_m || std::abs(landing.y()) > reach.max_offset_lateral_m) {
        return where + "landing point of " + kLegNames[leg] +
               format(" (x %.3f, y %.3f m) is outside the leg's reach (|x| <= %.2f", landing.x(), landing.y(),
                      reach.max_offset_forward_m) +
               format(", |y| <= %.2f m from under the hip)", reach.max_offset_lateral_m);
      }
    }
  }
  if (total_s > kMaxUserGaitS) {
    return format("the steps last %.1f s, more than %.0f s", total_s, kMaxUserGaitS);
  }
  return "";
}

std::string user_gait_file_problem(const UserGaitFile& file) {
  return file.kind == UserGaitFile::Kind::Definition ? definition_problem(file.definition)
                                                     : parameters_problem(file.parameters);
}

UserGaitStep decode_user_gait_step(const HighLevelCommand& step) {
  const UserGaitRanges ranges;
  UserGaitStep decoded;
  decoded.duration_s = std::max(0, step.duration) * 1e-3;
  decoded.velocity = {step.vel_des[0], step.vel_des[1], step.vel_des[2]};  // the controller clamps it
  // body_pos_des x, y arrive in pos_des[0:2] (the seed's converter: pos_des = body_pos_des[3:6]).
  // The seed integrates the velocity into the position "in this direction" and uses the file's
  // position only where no velocity is given: so axis by axis
  const std::array<Range, 2> offset_ranges{ranges.offset_x, ranges.offset_y};
  for (int axis = 0; axis < 2; ++axis) {
    if (std::abs(step.vel_des[axis]) < ranges.no_velocity_m_s) {
      decoded.position_offset_m[axis] = offset_ranges[axis].clamp(step.pos_des[axis]);
    }
  }
  decoded.legs.leans_to_position = !decoded.position_offset_m.isZero();
  decoded.pitch_rad = body_pitch_from_command(ranges.pitch.clamp(step.rpy_des[1]));
  decoded.height_m = step.pos_des[2] > 0.0f ? ranges.height.clamp(step.pos_des[2]) : kDefaultBodyHeightM;
  UserStepTargets& legs = decoded.legs;
  legs.roll_rad = ranges.roll.clamp(step.rpy_des[0]);
  legs.yaw_offset_rad = ranges.yaw_offset.clamp(step.rpy_des[2]);
  const std::array<double, kNumLegs> heights = step_heights_of(step);
  for (std::size_t leg = 0; leg < kNumLegs; ++leg) {
    legs.landing_offset_m[leg] = landing_of(step, leg);
    legs.step_height_m[leg] = ranges.step_height.clamp(heights[leg]);
  }
  const double gain = (step.contact % 100) * 0.1;
  legs.landing_gain = gain >= ranges.landing_gain.lower && gain <= ranges.landing_gain.upper ? gain : 1.0;
  const double mu = step.ctrl_point[2];
  legs.friction = mu >= ranges.friction.lower && mu <= ranges.friction.upper ? mu : 0.0;
  return decoded;
}

std::shared_ptr<const UserGaitProgram> build_user_gait_program(const UserGaitDefinition& definition,
                                                               const UserGaitParameters& parameters) {
  std::vector<ContactSequence::Section> sections;
  for (const GaitSection& section : definition.sections) sections.push_back({section.stance, section.duration_units});
  auto program = std::make_shared<UserGaitProgram>();
  program->sequence = std::make_shared<const ContactSequence>(sections);
  for (const HighLevelCommand& step : parameters.steps) program->steps.push_back(decode_user_gait_step(step));
  return program;
}

}  // namespace cerebellum
