#include "modes/transition_table.hpp"

#include <algorithm>
#include <initializer_list>

namespace cerebellum {
namespace {

using M = ModeId;

bool in(ModeId to, std::initializer_list<ModeId> allowed) {
  return std::find(allowed.begin(), allowed.end(), to) != allowed.end();
}

}  // namespace

bool is_known_mode(int mode) {
  switch (mode) {
    case 0: case 3: case 7: case 9: case 11: case 12: case 15: case 16: case 21: case 22: case 62: case 64:
      return true;
    default:
      return false;
  }
}

bool transition_allowed(ModeId from, ModeId to) {
  switch (from) {
    case M::Off: return in(to, {M::RecoveryStand, M::PoseControl, M::PureDamper, M::LowLevelMotor, M::Motion, M::Off});
    case M::QpStand: return in(to, {M::Locomotion, M::PureDamper, M::PoseControl, M::RecoveryStand, M::Off, M::QpStand});
    case M::PureDamper: return in(to, {M::Off, M::RecoveryStand, M::PureDamper, M::LowLevelMotor});
    // from Lifted: 11 and 3 only once landed, which the machine checks
    case M::Lifted: return in(to, {M::PureDamper, M::RecoveryStand, M::Off, M::Locomotion, M::QpStand});
    case M::Locomotion:
      return in(to, {M::RecoveryStand, M::Off, M::PureDamper, M::PoseControl, M::QpStand, M::Locomotion, M::Jump3d});
    case M::RecoveryStand: return true;
    case M::LowLevelMotor: return in(to, {M::Off, M::PureDamper, M::RecoveryStand});
    case M::Jump3d:
      return in(to, {M::RecoveryStand, M::Off, M::QpStand, M::PoseControl, M::Locomotion, M::PureDamper});
    case M::PoseControl:
      return in(to, {M::RecoveryStand, M::Off, M::PureDamper, M::PoseControl, M::QpStand, M::Locomotion, M::Motion,
                     M::Jump3d, M::TwoLegStand});
    case M::ForceJump:
      return in(to, {M::PoseControl, M::PureDamper, M::QpStand, M::RecoveryStand, M::Off, M::Locomotion,
                     M::TwoLegStand});
    case M::Motion: return in(to, {M::RecoveryStand, M::Off, M::PureDamper, M::PoseControl, M::QpStand});
    case M::TwoLegStand:
      return in(to, {M::RecoveryStand, M::Off, M::PureDamper, M::Jump3d, M::QpStand, M::PoseControl});
  }
  return false;
}

}  // namespace cerebellum
