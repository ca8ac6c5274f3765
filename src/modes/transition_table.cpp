#include "modes/transition_table.hpp"

#include <cstddef>
#include <cstdint>
#include <initializer_list>

namespace cerebellum {
namespace {

using M = ModeId;

// position of a mode in kAllModes (kAllModes.size() for an id outside it)
constexpr std::size_t mode_index(ModeId mode) {
  for (std::size_t i = 0; i < kAllModes.size(); ++i) {
    if (kAllModes[i].id == mode) return i;
  }
  return kAllModes.size();
}

// a set of modes as bits at their positions in kAllModes
using ModeBits = std::uint32_t;
static_assert(kAllModes.size() <= 32, "a ModeBits holds one bit per mode");

constexpr ModeBits modes(std::initializer_list<ModeId> list) {
  ModeBits set = 0;
  for (ModeId mode : list) set |= ModeBits{1} << mode_index(mode);
  return set;
}

constexpr ModeBits every_mode() {
  ModeBits set = 0;
  for (const ModeInfo& info : kAllModes) set |= modes({info.id});
  return set;
}

struct Row {
  ModeId from;
  ModeBits to;
};

// one row per mode, in the order of kAllModes
constexpr std::array<Row, kAllModes.size()> kTable{{
    {M::Off, modes({M::RecoveryStand, M::PoseControl, M::PureDamper, M::LowLevelMotor, M::Motion, M::Off})},
    {M::QpStand, modes({M::Locomotion, M::PureDamper, M::PoseControl, M::RecoveryStand, M::Off, M::QpStand})},
    {M::PureDamper, modes({M::Off, M::RecoveryStand, M::PureDamper, M::LowLevelMotor})},
    // from Lifted: 11 and 3 only once landed, which the machine checks
    {M::Lifted, modes({M::PureDamper, M::RecoveryStand, M::Off, M::Locomotion, M::QpStand})},
    {M::Locomotion,
     modes({M::RecoveryStand, M::Off, M::PureDamper, M::PoseControl, M::QpStand, M::Locomotion, M::Jump3d})},
    {M::RecoveryStand, every_mode()},
    {M::LowLevelMotor, modes({M::Off, M::PureDamper, M::RecoveryStand})},
    {M::Jump3d, modes({M::RecoveryStand, M::Off, M::QpStand, M::PoseControl, M::Locomotion, M::PureDamper})},
    {M::PoseControl, modes({M::RecoveryStand, M::Off, M::PureDamper, M::PoseControl, M::QpStand, M::Locomotion,
                            M::Motion, M::Jump3d, M::TwoLegStand})},
    {M::ForceJump,
     modes({M::PoseControl, M::PureDamper, M::QpStand, M::RecoveryStand, M::Off, M::Locomotion, M::TwoLegStand})},
    {M::Motion, modes({M::RecoveryStand, M::Off, M::PureDamper, M::PoseControl, M::QpStand})},
    {M::TwoLegStand, modes({M::RecoveryStand, M::Off, M::PureDamper, M::Jump3d, M::QpStand, M::PoseControl})},
}};

constexpr bool rows_follow_the_mode_list() {
  for (std::size_t i = 0; i < kAllModes.size(); ++i) {
    if (kTable[i].from != kAllModes[i].id) return false;
  }
  return true;
}
static_assert(rows_follow_the_mode_list(), "the transition table has one row per mode, in the order of kAllModes");

}  // namespace

bool is_known_mode(int mode) { return find_mode(mode) != nullptr; }

bool transition_allowed(ModeId from, ModeId to) {
  const std::size_t row = mode_index(from);
  const std::size_t column = mode_index(to);
  if (row == kAllModes.size() || column == kAllModes.size()) return false;
  return (kTable[row].to & (ModeBits{1} << column)) != 0;
}

}  // namespace cerebellum
