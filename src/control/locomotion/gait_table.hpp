// Every gait of mode 11, once: the firmware's reference table (contact pattern and velocity
// limits) plus what this MC adds (name, kind, default step height). The contact schedules, the
// command clamps, the MC's assembly and `cerebellum cmd` all read it.
#pragma once

#include <array>

#include "core/joint_layout.hpp"

namespace cerebellum {

enum class GaitKind {
  Stand,              // all feet stay down (served by the stand or by the MPC with all-stance)
  Walking,            // a fixed cycle on the walking controller
  FrequencyAdapting,  // the walking controller picks the cycle from the commanded speed
};

// one segment of a contact schedule, and one MPC step: the reference's 30 ms unit (a user gait's
// section durations count in it too)
inline constexpr double kGaitSegmentS = 0.03;

// a walking cycle in segments of kGaitSegmentS
struct GaitCycle {
  int period_segments;
  int stance_segments;  // every leg's stance length
};

// the gait table's default swing height, for those that give none: a walking-controller target
// that sets none (before the first command, the uploaded gait's closing stand) and clients that
// send a gait's default (the in-process lockstep client, loop/lockstep_client.hpp). It is no
// fallback for a commanded step height: mode 11 clamps that to kStepHeightRange
// (modes/command_ranges.hpp, 0.005..0.06 m), so 0 walks at the 5 mm floor
inline constexpr double kDefaultStepHeightM = 0.06;

// gait ids other code names: the stand that pulls the body back over its feet after a push (also
// the controller's resting gait), the stand that only damps a push, the frequency-adapting trot
inline constexpr int kStandGaitId = 1;
inline constexpr int kStandWithoutPushRecoveryGaitId = 31;
inline constexpr int kVariableTrotGaitId = 26;
// the flying trot (the AlienGo interface's running trot) and the slow trot (its stairs gait, and
// the `cerebellum walk` default)
inline constexpr int kFlyingTrotGaitId = 10;
inline constexpr int kSlowTrotGaitId = 27;
// the pronk: its flight is the longest of the table, the most a user gait may fly
inline constexpr int kPronkGaitId = 2;
// the passive trot ("walk the dog"): stands until pulled, then trots along with the pull
inline constexpr int kPassiveTrotGaitId = 4;
// the uploaded user gait (user_gait_file), run by mode 11 and mode 62 with this gait id
inline constexpr int kUserGaitId = 110;

// the stand a walking gait comes to rest in when its timed entry ends or a lifted robot is set
// down (cyberdog2-highlevel.md): gait 1 after gaits up to 30, gait 31 after the others
inline constexpr int kLastGaitRestingInStandGaitId = 30;
constexpr int resting_gait_of(int walking_gait_id) {
  return walking_gait_id <= kLastGaitRestingInStandGaitId ? kStandGaitId : kStandWithoutPushRecoveryGaitId;
}

struct GaitSpec {
  int id;
  const char* name;
  GaitKind kind;
  GaitCycle cycle;                    // for a frequency-adapting gait: the cycle at rest
  std::array<int, kNumLegs> offsets;  // segment in which stance starts (FR, FL, RR, RL)
  // velocity limits (vx, vy m/s; yaw rate rad/s), clamped, not rejected; zero for stands
  std::array<double, 3> velocity_min;
  std::array<double, 3> velocity_max;
  double default_step_height_m;
};

inline constexpr std::array<GaitSpec, 9> kGaitTable{{
    {kStandGaitId, "stand", GaitKind::Stand, {10, 10}, {0, 0, 0, 0}, {0, 0, 0}, {0, 0, 0}, kDefaultStepHeightM},
    {2,
     "pronk",
     GaitKind::Walking,
     {10, 4},
     {0, 0, 0, 0},
     {-0.10, -0.15, -0.50},
     {0.20, 0.15, 0.50},
     kDefaultStepHeightM},
    {3,
     "medium trot",
     GaitKind::Walking,
     {12, 6},
     {0, 6, 6, 0},
     {-1.2, -0.4, -2.25},
     {1.2, 0.4, 2.25},
     kDefaultStepHeightM},
    {kPassiveTrotGaitId,
     "walk-dog trot",
     GaitKind::Walking,
     {12, 6},
     {0, 6, 6, 0},
     {-0.65, -0.4, -0.80},
     {0.65, 0.4, 0.80},
     kDefaultStepHeightM},
    {7, "bound", GaitKind::Walking, {12, 8}, {6, 6, 0, 0}, {-0.3, -0.3, -1.5}, {0.3, 0.3, 1.5}, kDefaultStepHeightM},
    {kFlyingTrotGaitId,
     "flying trot",
     GaitKind::Walking,
     {10, 4},
     {0, 5, 5, 0},
     {-1.2, -0.55, -2.5},
     {1.6, 0.55, 2.5},
     kDefaultStepHeightM},
    {kVariableTrotGaitId,
     "variable-frequency trot",
     GaitKind::FrequencyAdapting,
     {24, 16},
     {0, 12, 12, 0},
     {-1.2, -0.6, -2.5},
     {1.6, 0.6, 2.5},
     kDefaultStepHeightM},
    {kSlowTrotGaitId,
     "slow trot",
     GaitKind::Walking,
     {20, 12},
     {0, 10, 10, 0},
     {-0.60, -0.2, -1.30},
     {0.60, 0.2, 1.30},
     kDefaultStepHeightM},
    {kStandWithoutPushRecoveryGaitId,
     "stand without push recovery",
     GaitKind::Stand,
     {10, 10},
     {0, 0, 0, 0},
     {0, 0, 0},
     {0, 0, 0},
     kDefaultStepHeightM},
}};

// the variable-frequency trot (26): its cycles as the commanded speed grows, one step per 0.2 m/s;
// a trot (diagonal pairs half a cycle apart) on each
inline constexpr double kVariableTrotSpeedPerCycleMPerS = 0.2;
inline constexpr std::array<GaitCycle, 8> kVariableTrotCycles{
    {{24, 16}, {22, 14}, {20, 12}, {18, 11}, {16, 10}, {14, 8}, {12, 6}, {10, 5}}};

// the table's entry of a gait id, or nullptr for an id mode 11 does not know
constexpr const GaitSpec* find_gait(int gait_id) {
  for (const GaitSpec& gait : kGaitTable) {
    if (gait.id == gait_id) return &gait;
  }
  return nullptr;
}

// the variable trot's entry is its cycle at rest, as a trot
static_assert(find_gait(kVariableTrotGaitId)->cycle.period_segments == kVariableTrotCycles[0].period_segments &&
              find_gait(kVariableTrotGaitId)->cycle.stance_segments == kVariableTrotCycles[0].stance_segments &&
              find_gait(kVariableTrotGaitId)->offsets[1] == kVariableTrotCycles[0].period_segments / 2);

// true for the gaits that step (walking and frequency-adapting), false for stands
constexpr bool gait_steps(const GaitSpec& gait) { return gait.kind != GaitKind::Stand; }

}  // namespace cerebellum
