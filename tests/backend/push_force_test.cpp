// The viewer's push: a limited spring-damper pulling the trunk towards the mouse's target.
#include "backend/push_request.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cerebellum {
namespace {

TEST(PushForce, NoForceWithoutAnActiveRequest) {
  PushRequest request;
  request.target_world = {1.0, 2.0, 3.0};
  const auto force = push_force(request, {0, 0, 0}, {1, 1, 1}, PushSpring{});
  EXPECT_EQ(force, (std::array<double, 3>{0, 0, 0}));
}

TEST(PushForce, SpringMinusDampingBelowTheLimit) {
  const PushSpring spring{100.0, 10.0, 1000.0};
  const PushRequest request{true, {0.1, -0.2, 0.3}};
  const auto force = push_force(request, {0.0, 0.0, 0.25}, {0.2, 0.0, -0.1}, spring);
  // by hand: 100 * (0.1, -0.2, 0.05) - 10 * (0.2, 0, -0.1)
  EXPECT_NEAR(force[0], 10.0 - 2.0, 1e-12);
  EXPECT_NEAR(force[1], -20.0, 1e-12);
  EXPECT_NEAR(force[2], 5.0 + 1.0, 1e-12);
}

TEST(PushForce, LimitedInMagnitudeKeepingTheDirection) {
  const PushSpring spring{150.0, 15.0, 40.0};
  const PushRequest request{true, {3.0, 4.0, 0.0}};
  const auto force = push_force(request, {0, 0, 0}, {0, 0, 0}, spring);
  EXPECT_NEAR(std::hypot(force[0], force[1], force[2]), 40.0, 1e-9);
  EXPECT_NEAR(force[0], 40.0 * 0.6, 1e-9);
  EXPECT_NEAR(force[1], 40.0 * 0.8, 1e-9);
  EXPECT_NEAR(force[2], 0.0, 1e-12);
}

}  // namespace
}  // namespace cerebellum
