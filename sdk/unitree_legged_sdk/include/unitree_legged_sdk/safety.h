// The robot kind the vendor's examples name when they construct their Safety helper. High-level
// programs only construct it: the MC applies the protections (docs/aliengo-udp.md).
#pragma once

namespace UNITREE_LEGGED_SDK {

enum class LeggedType { Aliengo, A1, Go1, B1, Laikago };

class Safety {
 public:
  explicit Safety(LeggedType type) : type_(type) {}
  LeggedType type() const { return type_; }

 private:
  LeggedType type_;
};

}  // namespace UNITREE_LEGGED_SDK
