#include "control/flip_plan/planar_model.hpp"

namespace cerebellum::flip {

std::vector<PlanarBody> planar_bodies() {
  using namespace robot;
  std::vector<PlanarBody> bodies;
  bodies.push_back({0, kFrontPair, {kBodyLink.com_m[0], kBodyLink.com_m[2]}, kBodyLink.mass_kg, kBodyLink.inertia_yy_kg_m2});
  for (int pair = 0; pair < kPairs; ++pair) {
    const double side = pair == kFrontPair ? 1.0 : -1.0;
    const auto hip = pair_hip_m(pair);
    // the abad links, the abad rotors and the hip rotors do not pitch against the trunk: trunk parts.
    // A rotor's inertia counts twice over: its own body turning with the link it sits on (here:
    // the abad rotor across its axis, the hip and knee rotors about theirs), and its spin through
    // the gear relative to that link (the joint's armature, in dynamics_residual)
    bodies.push_back({0, pair, {hip[0] + kAbadLink.com_m[0], hip[1] + kAbadLink.com_m[2]}, kLegsPerPair * kAbadLink.mass_kg,
                      kLegsPerPair * kAbadLink.inertia_yy_kg_m2});
    bodies.push_back({0, pair, {side * kAbadRotorX, 0.0}, kLegsPerPair * kRotorMassKg, kLegsPerPair * kRotorCrossInertiaKgM2});
    bodies.push_back({0, pair, hip, kLegsPerPair * kRotorMassKg, kLegsPerPair * kRotorAxialInertiaKgM2});
    bodies.push_back({1, pair, {kThighLink.com_m[0], kThighLink.com_m[2]}, kLegsPerPair * kThighLink.mass_kg,
                      kLegsPerPair * kThighLink.inertia_yy_kg_m2});
    bodies.push_back({1, pair, {0.0, -kKneeRotorOffsetM}, kLegsPerPair * kRotorMassKg, kLegsPerPair * kRotorAxialInertiaKgM2});
    bodies.push_back({2, pair, {kShankLink.com_m[0], kShankLink.com_m[2]}, kLegsPerPair * kShankLink.mass_kg,
                      kLegsPerPair * kShankLink.inertia_yy_kg_m2});
  }
  return bodies;
}

double planar_total_mass_kg(const std::vector<PlanarBody>& bodies) {
  double mass_kg = 0.0;
  for (const PlanarBody& body : bodies) mass_kg += body.mass_kg;
  return mass_kg;
}

}  // namespace cerebellum::flip
