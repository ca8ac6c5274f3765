// Filling the float fields of LCM messages from the MC's double-precision values.
#pragma once

#include <Eigen/Core>

namespace cerebellum {

// a 3-vector into a message's float[3] field
inline void put_vector3(float* out, const Eigen::Vector3d& v) {
  for (int i = 0; i < 3; ++i) out[i] = static_cast<float>(v[i]);
}

}  // namespace cerebellum
