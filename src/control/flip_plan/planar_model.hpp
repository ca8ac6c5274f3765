// The robot seen from its side, for planning flips offline: the trunk (x, z, pitch) and two lumped
// legs (the front pair and the rear pair, each leg of a pair doing the same), every mass, length
// and inertia taken from core/robot_model.hpp. The equations are written as inverse dynamics
// (Kane's method: partial velocities times inertia and gravity forces) on a scalar template, so the
// planner differentiates them exactly with forward-mode automatic differentiation.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "core/robot_model.hpp"

namespace cerebellum::flip {

// generalised coordinates: the trunk frame's origin (m) and pitch (rad, SDK sign: positive pitches
// the nose down, so a back flip turns it by -2 pi), then the pairs' hip and knee angles (rad, SDK)
enum Coordinate : int { kX = 0, kZ, kPitch, kFrontHip, kFrontKnee, kRearHip, kRearKnee, kDof };
inline constexpr int kPairs = 2;
enum Pair : int { kFrontPair = 0, kRearPair = 1 };
inline constexpr int hip_coordinate(int pair) { return pair == kFrontPair ? kFrontHip : kRearHip; }
inline constexpr int knee_coordinate(int pair) { return hip_coordinate(pair) + 1; }
// legs per pair: a pair's masses, inertias and motors count twice
inline constexpr double kLegsPerPair = 2.0;

// one rigid part of the planar model: where its centre of mass sits on the chain (0 the trunk,
// 1 a thigh, 2 a shank) of which pair, its offset in that link's frame (x, z), its mass and its
// inertia about the pitch axis
struct PlanarBody {
  int depth;
  int pair;
  std::array<double, 2> offset_m;
  double mass_kg;
  double inertia_yy_kg_m2;
};

// the bodies of the model built from core/robot_model.hpp (both legs of a pair lumped)
std::vector<PlanarBody> planar_bodies();
double planar_total_mass_kg(const std::vector<PlanarBody>& bodies);

// the pair's hip joint in the trunk frame (x, z)
inline std::array<double, 2> pair_hip_m(int pair) { return {pair == kFrontPair ? robot::kHipX : -robot::kHipX, 0.0}; }

template <typename T>
struct Point2 {
  T x;
  T z;
};

// R_y(angle) applied to (x, z): the SDK's pitch sense
template <typename T>
Point2<T> rotate(const T& angle, double x, double z) {
  using std::cos;
  using std::sin;
  return {cos(angle) * x + sin(angle) * z, -sin(angle) * x + cos(angle) * z};
}
// d/d(angle) of rotate(angle, x, z)
template <typename T>
Point2<T> rotate_derivative(const T& angle, double x, double z) {
  using std::cos;
  using std::sin;
  return {-sin(angle) * x + cos(angle) * z, -cos(angle) * x - sin(angle) * z};
}

// the chain from the trunk origin to a point at `depth` on `pair` with `offset` in its link's
// frame: up to three segments, each turned by the trunk's pitch plus the joints above it
struct ChainSegment {
  int depth;  // 0: turned by the pitch; 1: + hip; 2: + hip + knee
  double x;
  double z;
};
inline int chain_segments(int depth, int pair, const std::array<double, 2>& offset_m, ChainSegment out[3]) {
  if (depth == 0) {
    out[0] = {0, offset_m[0], offset_m[1]};
    return 1;
  }
  const auto hip = pair_hip_m(pair);
  out[0] = {0, hip[0], hip[1]};
  if (depth == 1) {
    out[1] = {1, offset_m[0], offset_m[1]};
    return 2;
  }
  out[1] = {1, 0.0, -robot::kThighLength};
  out[2] = {2, offset_m[0], offset_m[1]};
  return 3;
}

// the angle of a segment at `depth` of `pair` and whether coordinate j turns it
template <typename T>
T segment_angle(const T* q, int depth, int pair) {
  T angle = q[kPitch];
  if (depth >= 1) angle = angle + q[hip_coordinate(pair)];
  if (depth >= 2) angle = angle + q[knee_coordinate(pair)];
  return angle;
}
inline bool turns_segment(int coordinate, int depth, int pair) {
  if (coordinate == kPitch) return true;
  if (coordinate == hip_coordinate(pair)) return depth >= 1;
  if (coordinate == knee_coordinate(pair)) return depth >= 2;
  return false;
}

// where a point of the chain is (world x, z)
template <typename T>
Point2<T> chain_position(const T* q, int depth, int pair, const std::array<double, 2>& offset_m) {
  ChainSegment segments[3];
  const int n = chain_segments(depth, pair, offset_m, segments);
  Point2<T> p{q[kX], q[kZ]};
  for (int s = 0; s < n; ++s) {
    const Point2<T> r = rotate(segment_angle(q, segments[s].depth, pair), segments[s].x, segments[s].z);
    p.x = p.x + r.x;
    p.z = p.z + r.z;
  }
  return p;
}

// d(point velocity)/d(qd_j): the partial velocity of coordinate j
template <typename T>
Point2<T> chain_partial_velocity(const T* q, int depth, int pair, const std::array<double, 2>& offset_m, int j) {
  if (j == kX) return {T(1.0), T(0.0)};
  if (j == kZ) return {T(0.0), T(1.0)};
  ChainSegment segments[3];
  const int n = chain_segments(depth, pair, offset_m, segments);
  Point2<T> v{T(0.0), T(0.0)};
  for (int s = 0; s < n; ++s) {
    if (!turns_segment(j, segments[s].depth, pair)) continue;
    const Point2<T> d = rotate_derivative(segment_angle(q, segments[s].depth, pair), segments[s].x, segments[s].z);
    v.x = v.x + d.x;
    v.z = v.z + d.z;
  }
  return v;
}

// the point's acceleration: each segment turning at its angle's rate adds R' r alpha - R r omega^2
template <typename T>
Point2<T> chain_acceleration(const T* q, const T* qd, const T* qdd, int depth, int pair,
                             const std::array<double, 2>& offset_m) {
  ChainSegment segments[3];
  const int n = chain_segments(depth, pair, offset_m, segments);
  Point2<T> a{qdd[kX], qdd[kZ]};
  for (int s = 0; s < n; ++s) {
    const T angle = segment_angle(q, segments[s].depth, pair);
    const T rate = segment_angle(qd, segments[s].depth, pair);
    const T rate_dot = segment_angle(qdd, segments[s].depth, pair);
    const Point2<T> r = rotate(angle, segments[s].x, segments[s].z);
    const Point2<T> d = rotate_derivative(angle, segments[s].x, segments[s].z);
    a.x = a.x + d.x * rate_dot - r.x * rate * rate;
    a.z = a.z + d.z * rate_dot - r.z * rate * rate;
  }
  return a;
}

// a pair's foot centre (world x, z); the ground touches it kFootRadius below
inline const std::array<double, 2> kFootOffsetM{0.0, -robot::kShankLength};
template <typename T>
Point2<T> foot_position(const T* q, int pair) {
  return chain_position(q, 2, pair, kFootOffsetM);
}

// the generalised forces the motion (q, qd, qdd) needs beyond what the motors and the ground give:
// residual = sum_b [m_b v_bj . (a_b - g) + I_b w_bj alpha_b] + armature qdd_j - tau_j - sum_f v_fj . f.
// Zero where the motion obeys the model. joint_torque_nm: per motor (front hip, front knee, rear
// hip, rear knee), each pair's two motors alike; foot_force_n: the ground's force on one foot of
// each pair (front x, z, rear x, z)
template <typename T>
void dynamics_residual(const std::vector<PlanarBody>& bodies, const T* q, const T* qd, const T* qdd,
                       const T* joint_torque_nm, const T* foot_force_n, T* residual) {
  for (int j = 0; j < kDof; ++j) residual[j] = T(0.0);
  for (const PlanarBody& body : bodies) {
    const Point2<T> a = chain_acceleration(q, qd, qdd, body.depth, body.pair, body.offset_m);
    const T alpha = segment_angle(qdd, body.depth, body.pair);
    for (int j = 0; j < kDof; ++j) {
      const Point2<T> v = chain_partial_velocity(q, body.depth, body.pair, body.offset_m, j);
      T generalised = body.mass_kg * (v.x * a.x + v.z * (a.z + robot::kGravityMPerS2));
      if (j >= kPitch && turns_segment(j, body.depth, body.pair))
        generalised = generalised + body.inertia_yy_kg_m2 * alpha;
      residual[j] = residual[j] + generalised;
    }
  }
  for (int pair = 0; pair < kPairs; ++pair) {
    for (int joint = 0; joint < 2; ++joint) {
      const int j = hip_coordinate(pair) + joint;
      residual[j] = residual[j] + kLegsPerPair * robot::kJointArmatureKgM2 * qdd[j] -
                    kLegsPerPair * joint_torque_nm[2 * pair + joint];
    }
    for (int j = 0; j < kDof; ++j) {
      const Point2<T> v = chain_partial_velocity(q, 2, pair, kFootOffsetM, j);
      residual[j] = residual[j] - kLegsPerPair * (v.x * foot_force_n[2 * pair] + v.z * foot_force_n[2 * pair + 1]);
    }
  }
}

}  // namespace cerebellum::flip
