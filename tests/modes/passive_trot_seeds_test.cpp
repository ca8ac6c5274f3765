// Gait 4, the passive trot, over noise seeds, pull directions and timings: the cases of
// passive_trot_cases.cpp beyond the one of each that test_modes_sim runs. Long (about 20 s each
// sanitized): left out of the sanitized stage (label seeds); the Release stage runs them.
#include <gtest/gtest.h>

#include "passive_trot_watch.hpp"

namespace cerebellum {
namespace testing {
namespace {

// 0: no sensor noise; else the noise's seed
INSTANTIATE_TEST_SUITE_P(NoiseSeeds, PassiveTrotAlone, ::testing::Values(11u, 12u));

INSTANTIATE_TEST_SUITE_P(FifteenNewtons, PassiveTrotPull,
                         ::testing::Values(PullCase{-15.0, 0.0, 0}, PullCase{0.0, 15.0, 0}, PullCase{15.0, 0.0, 11},
                                           PullCase{0.0, -15.0, 12},
                                           // fresh seeds and directions, not looked at while tuning
                                           PullCase{10.6, 10.6, 31}, PullCase{-10.6, -10.6, 32},
                                           PullCase{-15.0, 0.0, 33}, PullCase{0.0, 15.0, 34},
                                           PullCase{10.6, -10.6, 35}));

INSTANTIATE_TEST_SUITE_P(WaitsPullsAndStepHeights, PassiveTrotLatePull,
                         ::testing::Values(LatePullCase{0.5, 1.0, 0.05f, 0}, LatePullCase{2.0, 1.0, 0.05f, 0},
                                           LatePullCase{2.0, 3.0, 0.05f, 0}, LatePullCase{5.0, 4.0, 0.05f, 0},
                                           LatePullCase{3.0, 2.0, 0.05f, 41}, LatePullCase{1.0, 3.0, 0.0f, 42},
                                           LatePullCase{5.0, 1.0, 0.0f, 0}));

}  // namespace
}  // namespace testing
}  // namespace cerebellum
