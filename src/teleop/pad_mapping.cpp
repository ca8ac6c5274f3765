#include "teleop/pad_mapping.hpp"

#include <cmath>
#include <cstdio>

#include "control/locomotion/gait_table.hpp"
#include "modes/command_ranges.hpp"
#include "modes/jump_mode.hpp"

namespace cerebellum {
namespace {

// the gaits a person drives with the sticks: every stepping gait of the table but the passive trot,
// which follows a pull on the trunk, not the velocity command
constexpr bool drivable(const GaitSpec& gait) { return gait_steps(gait) && gait.id != kPassiveTrotGaitId; }

constexpr std::size_t drivable_count() {
  std::size_t count = 0;
  for (const GaitSpec& gait : kGaitTable) count += drivable(gait) ? 1 : 0;
  return count;
}

constexpr std::array<int, drivable_count()> drivable_gaits() {
  std::array<int, drivable_count()> ids{};
  std::size_t next = 0;
  for (const GaitSpec& gait : kGaitTable) {
    if (drivable(gait)) ids[next++] = gait.id;
  }
  return ids;
}

constexpr std::array<int, drivable_count()> kDrivableGaits = drivable_gaits();

// the first gait the sticks walk with: the slow trot, the steadiest (also `cerebellum cmd walk`'s)
constexpr std::size_t first_gait_index() {
  for (std::size_t i = 0; i < kDrivableGaits.size(); ++i) {
    if (kDrivableGaits[i] == kSlowTrotGaitId) return i;
  }
  return 0;
}

HighLevelCommand mode_command(ModeId mode, int gait_id) {
  HighLevelCommand command;
  command.mode = static_cast<int>(mode);
  command.gait_id = gait_id;
  command.contact = 0x0F;
  return command;
}

HighLevelCommand action_command(PadAction action) {
  switch (action) {
    case PadAction::Damp: return mode_command(ModeId::PureDamper, 0);
    case PadAction::Stand: return mode_command(ModeId::RecoveryStand, 0);
    case PadAction::LieDown: return mode_command(ModeId::PureDamper, 1);
    case PadAction::Motion: return mode_command(ModeId::Motion, kPadMotionId);
    case PadAction::Jump: return mode_command(ModeId::Jump3d, kPadJumpId);
    case PadAction::NextGait: break;  // built from the sticks
  }
  return {};
}

// the sticks walk the robot from a stand, a walk, or the stand a jump ends in; lying, damped or in
// a motion (which mode 11 may not interrupt) they wait for a button
bool sticks_drive_from(const HighLevelCommand& last) {
  return last.mode == static_cast<int>(ModeId::RecoveryStand) || last.mode == static_cast<int>(ModeId::Locomotion) ||
         last.mode == static_cast<int>(ModeId::Jump3d);
}

bool stick_moved(const PadState& pad) {
  for (const double axis : {pad.left_x, pad.left_y, pad.right_x, pad.right_y, pad.left_trigger, pad.right_trigger}) {
    if (stick_after_dead_zone(axis) != 0.0) return true;
  }
  return false;
}

// a deflection in [-1, 1] onto the gait's range: full forward is the gait's max, full back its min
double scale(double deflection, double min, double max) {
  return deflection >= 0.0 ? deflection * max : -deflection * min;
}

bool same_command(const HighLevelCommand& a, const HighLevelCommand& b) {
  return a.mode == b.mode && a.gait_id == b.gait_id && a.contact == b.contact && a.vel_des == b.vel_des &&
         a.rpy_des == b.rpy_des && a.pos_des == b.pos_des && a.step_height == b.step_height && a.value == b.value &&
         a.duration == b.duration;
}

}  // namespace

int pad_gait_count() { return static_cast<int>(kDrivableGaits.size()); }
int pad_gait_at(int index) { return kDrivableGaits.at(static_cast<std::size_t>(index)); }

double stick_after_dead_zone(double axis) {
  const double magnitude = std::min(std::abs(axis), 1.0);
  if (!(magnitude > kStickDeadZone)) return 0.0;  // NaN too
  return std::copysign((magnitude - kStickDeadZone) / (1.0 - kStickDeadZone), axis);
}

PadMapping::PadMapping() : gait_index_(first_gait_index()) {}

int PadMapping::gait_id() const { return kDrivableGaits[gait_index_]; }

HighLevelCommand PadMapping::walk(const PadState& pad) const {
  const GaitSpec& gait = *find_gait(gait_id());
  HighLevelCommand command = mode_command(ModeId::Locomotion, gait.id);
  // forward is up on the left stick; y and yaw point left, the sticks' x right
  const double forward = stick_after_dead_zone(pad.left_y);
  const double left = -stick_after_dead_zone(pad.left_x);
  const double turn_left = -stick_after_dead_zone(pad.right_x);
  command.vel_des[0] = static_cast<float>(scale(forward, gait.velocity_min[0], gait.velocity_max[0]));
  command.vel_des[1] = static_cast<float>(scale(left, gait.velocity_min[1], gait.velocity_max[1]));
  command.vel_des[2] = static_cast<float>(scale(turn_left, gait.velocity_min[2], gait.velocity_max[2]));
  // mode 11's body pose: the right stick up raises the head (rpy_des[1] > 0), the right trigger
  // raises the body to the top of the range, the left one lowers it to the bottom
  const LocomotionStandRanges pose;
  command.rpy_des[1] =
      static_cast<float>(scale(stick_after_dead_zone(pad.right_y), pose.pitch.lower, pose.pitch.upper));
  command.pos_des[2] = static_cast<float>(
      pose.default_height_m + stick_after_dead_zone(pad.right_trigger) * (pose.height.upper - pose.default_height_m) -
      stick_after_dead_zone(pad.left_trigger) * (pose.default_height_m - pose.height.lower));
  command.step_height = {static_cast<float>(gait.default_step_height_m),
                         static_cast<float>(gait.default_step_height_m)};
  return command;
}

DriveStep PadMapping::emit(const HighLevelCommand& command) {
  DriveStep step{command, !sent_any_ || !same_command(command, last_)};
  last_ = command;
  sent_any_ = true;
  return step;
}

DriveStep PadMapping::next(const PadState& pad) {
  // the table's order decides between buttons pressed in one sample: damp first
  for (const ButtonBinding& binding : kButtonBindings) {
    if (!pad.pressed[static_cast<std::size_t>(binding.button)]) continue;
    if (binding.action == PadAction::NextGait) {
      if (last_.mode == static_cast<int>(ModeId::Locomotion)) gait_index_ = (gait_index_ + 1) % kDrivableGaits.size();
      sent_any_ = false;  // a press is always a new command
      return emit(walk(pad));
    }
    // a press is always new: the same jump twice jumps twice
    sent_any_ = false;
    return emit(action_command(binding.action));
  }
  if (!sent_any_) return {};  // nothing to say before the first button
  if (sticks_drive_from(last_) && (last_.mode == static_cast<int>(ModeId::Locomotion) || stick_moved(pad))) {
    return emit(walk(pad));
  }
  return emit(last_);
}

DriveStep PadMapping::stop() {
  if (!sent_any_) return {};
  HighLevelCommand still = last_;
  still.vel_des = {};  // the pose stays: only moving is stopped
  return emit(still);
}

std::string pad_mapping_help() {
  std::string out = "mapping (docs/driving.md):\n";
  char line[160];
  std::snprintf(line, sizeof line, "  left stick   forward/back, sideways (the gait's limits; dead zone %.0f %%)\n",
                kStickDeadZone * 100.0);
  out += line;
  out += "  right stick  x: yaw rate; y: pitch (up: head up)\n";
  const LocomotionStandRanges pose;
  std::snprintf(line, sizeof line, "  RT / LT      body height up / down (%.2f..%.2f m; released %.3f m)\n",
                pose.height.lower, pose.height.upper, pose.default_height_m);
  out += line;
  out += "  released     zero velocity (the robot trots in place; A stands it still)\n";
  for (const ButtonBinding& binding : kButtonBindings) {
    std::string what = binding.what;
    if (binding.action == PadAction::Motion) what += " (62/" + std::to_string(kPadMotionId) + ")";
    if (binding.action == PadAction::Jump) {
      what += " (16/" + std::to_string(kPadJumpId);
      for (const JumpSpec& jump : kJump3dTable) {
        if (jump.gait_id == kPadJumpId) what += std::string(": ") + jump.name;
      }
      what += ")";
    }
    std::snprintf(line, sizeof line, "  %-12s %s\n", binding.button_name, what.c_str());
    out += line;
  }
  out += "  walking gaits (Y):";
  for (const int id : kDrivableGaits) {
    std::snprintf(line, sizeof line, " %d %s%s", id, find_gait(id)->name, id == kDrivableGaits.back() ? "\n" : ",");
    out += line;
  }
  return out;
}

}  // namespace cerebellum
